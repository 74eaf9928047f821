#include "logview/log_cursor.h"

#include <algorithm>

namespace gnss::ui {

void LogCursor::setLog(const logview::LogView *log) {
    log_ = log;
    count_ = 0;
    current_ = 0;
    hasRange_ = false;
    emit indexChanged();
    emit rangeChanged();
    emit moved(0);
}

void LogCursor::notifyIndexChanged() {
    count_ = log_ ? log_->epochCount() : 0;
    if (count_ && current_ >= count_) current_ = count_ - 1;
    if (hasRange_ && count_) {
        first_ = std::min(first_, count_ - 1);
        last_ = std::min(last_, count_ - 1);
    }
    emit indexChanged();
}

void LogCursor::seek(std::size_t epoch, bool always) {
    if (count_ == 0) return;
    epoch = std::min(epoch, count_ - 1);
    if (epoch == current_ && !always) return;
    current_ = epoch;
    emit moved(epoch);
}

std::pair<std::size_t, std::size_t> LogCursor::selection() const {
    if (hasRange_) return {first_, last_};
    return {0, count_ ? count_ - 1 : 0};
}

void LogCursor::setRange(std::size_t first, std::size_t last) {
    if (count_ == 0) return;
    if (first > last) std::swap(first, last);
    first_ = std::min(first, count_ - 1);
    last_ = std::min(last, count_ - 1);
    hasRange_ = true;
    emit rangeChanged();
}

void LogCursor::setRangeStart(std::size_t first) {
    setRange(first, hasRange_ ? std::max(first, last_) : (count_ ? count_ - 1 : 0));
}

void LogCursor::setRangeEnd(std::size_t last) {
    setRange(hasRange_ ? std::min(first_, last) : 0, last);
}

void LogCursor::clearRange() {
    if (!hasRange_) return;
    hasRange_ = false;
    emit rangeChanged();
}

} // namespace gnss::ui
