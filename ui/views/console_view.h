#pragma once
// ConsoleView: received and sent lines (sent ones marked), checksum errors highlighted, filter by
// address, pause, clear, a hex view of the raw bytes, and a send box that adds the checksum,
// keeps a history and completes the dialect's command names.
//
// While a log is open it shows the log's own lines instead (showLog: any list model with
// ConsoleModel's roles, such as the viewer's virtual list over the file): the filter is then
// the model's to apply (filterChanged), the cursor's line is kept in view (showRow), a double
// click or Enter on a line asks for its moment (lineActivated), and the hex view shows the
// file's bytes up to the cursor.
#include <QStringList>
#include <QWidget>

#include <functional>

class QAbstractItemModel;
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
    // What is typed in the send box, not yet sent.
    QString typedCommand() const;
    void setFilter(const QString &addressPattern);
    int visibleLines() const;

    // A log's lines in place of the live ones (nullptr: back to the live console). `raw` gives
    // the bytes for the hex view.
    void showLog(QAbstractItemModel *lines, std::function<QByteArray()> raw = {});
    bool showingLog() const { return logLines_ != nullptr; }
    // Brings a row of the log's lines into view (the cursor's line), marked as the current one.
    void showRow(int row);
    // A line above the list (what a log's filter found); empty: none.
    void setNote(const QString &note);

    // Sends what the send box holds: completes the checksum, refuses a malformed sentence with a
    // message beside the box. Returns whether a sentence was emitted.
    bool submit();
    // Says beside the send box why a sentence emitted was not sent after all (the link refused
    // it: too long for the receiver, not connected); it stays in the history.
    void showNotSent(const QString &why);

signals:
    void sendRequested(const QByteArray &sentence);
    void filterChanged(const QString &addressPattern);
    void lineActivated(int row); // of the log's lines

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
    QToolButton *pause_;
    QToolButton *clear_;
    QLabel *note_;
    QAbstractItemModel *logLines_ = nullptr;
    std::function<QByteArray()> logRaw_;
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
