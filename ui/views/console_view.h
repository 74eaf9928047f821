#pragma once
// ConsoleView: received and sent lines (sent ones marked), checksum errors highlighted, filter by
// address, pause, clear, a hex view of the raw bytes, and a send box that adds the checksum,
// keeps a history and completes the dialect's command names.
#include <QStringList>
#include <QWidget>

class QLabel;
class QLineEdit;
class QListView;
class QPlainTextEdit;
class QPushButton;
class QSortFilterProxyModel;
class QStringListModel;
class QToolButton;

namespace gnss::ui {

class ConsoleModel;

class ConsoleView : public QWidget {
    Q_OBJECT
public:
    explicit ConsoleView(ConsoleModel *model, QWidget *parent = nullptr);

    // Command names offered for completion (the connected dialect's).
    void setCommandNames(const QStringList &names);
    // The connected receiver's example command for the send box's hint (empty: none known).
    void setExample(const QString &example);
    // Turns the send box off with the reason shown beside it ("gpsd owns the port: ..."), or on
    // again (empty): a link that takes no commands says so instead of refusing each one.
    void setSendRefusal(const QString &why);
    QString sendRefusal() const { return refusal_; }
    void setHistory(const QStringList &history);
    QStringList history() const { return history_; }
    void setFilter(const QString &addressPattern);
    int visibleLines() const;

    // Sends what the send box holds: completes the checksum, refuses a malformed sentence with a
    // message beside the box. Returns whether a sentence was emitted.
    bool submit();
    // Says beside the send box why a sentence emitted was not sent after all (the link refused
    // it: too long for the receiver, not connected); it stays in the history.
    void showNotSent(const QString &why);

signals:
    void sendRequested(const QByteArray &sentence);

protected:
    bool eventFilter(QObject *o, QEvent *e) override;

private:
    void setHex(bool on);
    void refreshHex();

    ConsoleModel *model_;
    QSortFilterProxyModel *proxy_;
    QListView *list_;
    QPlainTextEdit *hex_;
    QLineEdit *filter_;
    QLineEdit *input_;
    QPushButton *sendButton_;
    QLabel *inputError_;
    QLabel *sendNote_;
    QString refusal_;
    QString example_;
    QStringListModel *completions_;
    QStringList history_;
    int historyPos_ = -1;
    bool follow_ = true;
};

} // namespace gnss::ui
