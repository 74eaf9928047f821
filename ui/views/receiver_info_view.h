#pragma once
// ReceiverInfoView: model, firmware, the jamming indicator, and every status report the receiver
// gave (self-test, GeoStar status word and configuration registers, settings reports) as a tree
// of named flags. Vendor-neutral: it shows ReceiverState::reports, whatever they hold.
#include <QTimer>
#include <QWidget>

class QLabel;
class QTreeWidget;
class QTreeWidgetItem;
class QJsonValue;

namespace gnss::ui {

class ReceiverStateModel;

class ReceiverInfoView : public QWidget {
    Q_OBJECT
public:
    explicit ReceiverInfoView(ReceiverStateModel *model, QWidget *parent = nullptr);
    void refresh();
    QTreeWidget *tree() const { return tree_; }

private:
    void addJson(QTreeWidgetItem *parent, const QString &key, const QJsonValue &v);
    ReceiverStateModel *model_;
    QTimer timer_;
    bool dirty_ = true;
    QLabel *identity_;
    QLabel *jamming_;
    QTreeWidget *tree_;
    QString shownKey_; // what the tree shows, to rebuild only on change
};

} // namespace gnss::ui
