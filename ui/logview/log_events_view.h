#pragma once
// LogEventsView: the log's events in a list (fix changes, gaps, checksum bursts, time jumps,
// dialect changes, time marks, jamming, base station changes), filtered by kind; a click moves
// the cursor there, and the list can be saved as CSV.
#include "logview/log_cursor.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QTableWidget;
class QPushButton;

namespace gnss {
class DialectRegistry;
}

namespace gnss::ui {

class LogEventsView : public QWidget {
    Q_OBJECT
public:
    LogEventsView(LogCursor *cursor, const DialectRegistry &registry, QWidget *parent = nullptr);

    // The event's kind and its description in the user's language.
    static QString kindName(logview::EventKind k);
    QString describe(const logview::LogEvent &e) const;
    QTableWidget *table() const { return table_; }

signals:
    // Save the events as CSV (the application asks where).
    void exportRequested();

private:
    void reload();

    LogCursor *cursor_;
    const DialectRegistry &registry_;
    QComboBox *filter_;
    QTableWidget *table_;
    QPushButton *export_;
    QLabel *count_;
    std::vector<logview::LogEvent> events_;
};

} // namespace gnss::ui
