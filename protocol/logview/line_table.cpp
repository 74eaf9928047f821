#include "logview/line_table.h"

#include "core/framer.h"

#include <algorithm>
#include <cstring>

namespace gnss::logview {

LineRef LineTable::lineFrom(std::string_view data, std::uint64_t start, std::uint64_t &next) {
    const std::uint64_t size = data.size();
    if (start >= size) {
        next = size;
        return {size, 0};
    }
    const std::uint64_t limit = std::min<std::uint64_t>(size, start + Framer::kMaxLine);
    const char *p = data.data();
    const void *nl = std::memchr(p + start, '\n', limit - start);
    std::uint64_t end = nl ? static_cast<std::uint64_t>(static_cast<const char *>(nl) - p) : limit;
    next = nl ? end + 1 : end;
    if (end > start && p[end - 1] == '\r') --end;
    return {start, static_cast<std::uint32_t>(end - start)};
}

bool LineTable::extend(std::string_view data, const std::atomic<bool> *cancel) {
    const std::uint64_t size = data.size();
    if (size < scanned_) *this = LineTable{}; // truncated: count again
    const std::size_t keptStarts = starts_.size();
    std::uint64_t k = complete_;
    std::uint64_t pos = end_;
    bool open = false;
    const char *p = data.data();
    while (pos < size) {
        if (starts_.size() <= k / kStride) starts_.push_back(pos);
        const std::uint64_t limit = std::min<std::uint64_t>(size, pos + Framer::kMaxLine);
        const void *nl = std::memchr(p + pos, '\n', limit - pos);
        if (!nl && limit == size && size - pos < Framer::kMaxLine) {
            open = true; // the data ends inside this line: it may go on
            break;
        }
        pos = nl ? static_cast<std::uint64_t>(static_cast<const char *>(nl) - p) + 1 : limit;
        ++k;
        if ((k & 0xFFFF) == 0 && cancel && cancel->load(std::memory_order_relaxed)) {
            starts_.resize(keptStarts);
            return false;
        }
    }
    complete_ = k;
    end_ = pos;
    openLine_ = open;
    scanned_ = size;
    return true;
}

std::optional<LineRef> LineTable::line(std::string_view data, std::uint64_t k) const {
    if (k >= lineCount()) return std::nullopt;
    std::uint64_t pos = starts_[k / kStride];
    std::uint64_t next = pos;
    for (std::uint64_t i = k - k % kStride; i < k; ++i) {
        lineFrom(data, pos, next);
        pos = next;
    }
    return lineFrom(data, pos, next);
}

std::uint64_t LineTable::lineAt(std::string_view data, std::uint64_t offset) const {
    const std::uint64_t count = lineCount();
    if (count == 0) return 0;
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
    const std::size_t block = it == starts_.begin() ? 0 : std::size_t(it - starts_.begin()) - 1;
    std::uint64_t k = block * kStride;
    std::uint64_t pos = starts_[block];
    for (;; ++k) {
        std::uint64_t next = pos;
        lineFrom(data, pos, next);
        if (offset < next || k + 1 >= count || next <= pos) return k;
        pos = next;
    }
}

std::string_view LineTable::addressOf(std::string_view line) {
    if (line.empty() || (line.front() != '$' && line.front() != '!')) return {};
    std::size_t end = 1;
    while (end < line.size() && line[end] != ',' && line[end] != '*') ++end;
    std::string_view a = line.substr(1, end - 1);
    while (!a.empty() && a.back() == ' ') a.remove_suffix(1);
    return a;
}

bool LineTable::findLines(std::string_view data, const std::function<bool(std::string_view)> &keep,
                          std::size_t limit, Matches &m, const std::atomic<bool> *cancel) const {
    const std::uint64_t end = std::min<std::uint64_t>(end_, data.size());
    std::uint64_t pos = m.scannedTo;
    for (std::uint64_t n = 0; pos < end && !m.full; ++n) {
        std::uint64_t next = pos;
        const LineRef r = lineFrom(data, pos, next);
        if (keep(addressOf(data.substr(r.offset, r.length)))) {
            m.offsets.push_back(pos);
            m.full = m.offsets.size() >= limit;
        }
        pos = next;
        if ((n & 0xFFFF) == 0xFFFF && cancel && cancel->load(std::memory_order_relaxed)) {
            m.scannedTo = pos;
            return false;
        }
    }
    m.scannedTo = pos;
    return true;
}

} // namespace gnss::logview
