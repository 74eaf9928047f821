#pragma once
// LogCursor: the offline log viewer's one timeline. It holds the open log (the engine's LogView),
// the epoch under the cursor and the selected range; every log view (timeline strip, whole-log
// charts, track, events, range statistics) reads it and moves it, and the application publishes
// the receiver state at the cursor to the live docks. Knows no widget.
#include "logview/log_view.h"

#include <QObject>
#include <utility>

namespace gnss::ui {

class LogCursor : public QObject {
    Q_OBJECT
public:
    explicit LogCursor(QObject *parent = nullptr) : QObject(parent) {}

    // The log the views show (nullptr: none). Resets the cursor and the range.
    void setLog(const logview::LogView *log);
    const logview::LogView *log() const { return log_; }
    // Epochs indexed, as of the last indexChanged().
    std::size_t epochCount() const { return count_; }
    bool empty() const { return count_ == 0; }

    std::size_t current() const { return current_; }
    // Moves the cursor (clamped to the log); moved() when it changed or `always`.
    void seek(std::size_t epoch, bool always = false);

    bool hasRange() const { return hasRange_; }
    // The selected range, or the whole log when none is selected.
    std::pair<std::size_t, std::size_t> selection() const;
    void setRange(std::size_t first, std::size_t last);
    void setRangeStart(std::size_t first); // keeps the end (or the log's end)
    void setRangeEnd(std::size_t last);    // keeps the start (or the log's start)
    void clearRange();

    // The engine indexed more (ready, or a followed file grew): the count is read again.
    void notifyIndexChanged();

signals:
    void moved(std::size_t epoch);
    void rangeChanged();
    void indexChanged();

private:
    const logview::LogView *log_ = nullptr;
    std::size_t count_ = 0, current_ = 0;
    bool hasRange_ = false;
    std::size_t first_ = 0, last_ = 0;
};

} // namespace gnss::ui
