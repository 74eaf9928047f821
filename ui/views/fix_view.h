#pragma once
// FixView: the fix at a glance — badge, position (degrees or DMS), heights above sea level and
// ellipsoid, satellites, DOPs, UTC, speed and course, corrections. Refreshed on a timer.
#include <QTimer>
#include <QWidget>

class QLabel;
class QComboBox;
class QGridLayout;

namespace gnss::ui {

class ReceiverStateModel;

class FixView : public QWidget {
    Q_OBJECT
public:
    explicit FixView(ReceiverStateModel *model, QWidget *parent = nullptr);
    void setDegreesMinutesSeconds(bool dms);
    bool degreesMinutesSeconds() const { return dms_; }
    void refresh(); // what the timer does

private:
    QLabel *addRow(const QString &name, const QString &objectName);
    ReceiverStateModel *model_;
    QTimer timer_;
    bool dirty_ = true;
    bool dms_ = false;
    QComboBox *format_ = nullptr;
    QLabel *badge_ = nullptr;
    QGridLayout *grid_ = nullptr;
    QLabel *lat_, *lon_, *altMsl_, *altEll_, *sats_, *dops_, *utc_, *speed_, *course_, *corrAge_,
            *base_;
};

} // namespace gnss::ui
