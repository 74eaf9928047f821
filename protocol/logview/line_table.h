#pragma once
// LineTable: the lines of a mapped log as a virtual list, so that a console can scroll through a
// whole multi-gigabyte log without copying it: line k → its offset and length, the line holding
// an offset → its number.
//
// A line ends at '\n' (a CR before it is not part of the text); a run of bytes without '\n' is
// cut every Framer::kMaxLine bytes, as the framer cuts it. The table keeps the start of every
// kStride-th line (8 bytes per 256 lines: about half a megabyte for a 1 GB log); line k is found
// by stepping over at most kStride - 1 lines from the nearest one kept.
//
// It is extended as the data grows (a followed file): the last line, when the data ends before its
// '\n', is counted but looked at again by the next extend().
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace gnss::logview {

struct LineRef {
    std::uint64_t offset = 0;
    std::uint32_t length = 0; // without the line end
};

class LineTable {
public:
    static constexpr std::uint64_t kStride = 256;

    // Counts the lines of `data` past those counted before. `data` is the same log, possibly
    // longer (a shorter one, a truncated file, starts the count again). False when cancelled
    // (the table stays as it was).
    bool extend(std::string_view data, const std::atomic<bool> *cancel = nullptr);

    // Lines counted, the unfinished last one included.
    std::uint64_t lineCount() const { return complete_ + (openLine_ ? 1 : 0); }
    // Bytes of the data the count covers, and where its finished lines end.
    std::uint64_t scanned() const { return scanned_; }
    std::uint64_t completeEnd() const { return end_; }

    // Line k of `data` (the data extend() was last given, or a longer one).
    std::optional<LineRef> line(std::string_view data, std::uint64_t k) const;
    // The number of the line holding `offset` (the last line for an offset past the end).
    std::uint64_t lineAt(std::string_view data, std::uint64_t offset) const;

    // The line starting at `start`, and where the next one starts.
    static LineRef lineFrom(std::string_view data, std::uint64_t start, std::uint64_t &next);

    // The matches of a filter over the lines (a console filtered by address): the offsets of the
    // lines whose address `keep` takes, at most `limit` of them, found from `scannedTo` on.
    struct Matches {
        std::vector<std::uint64_t> offsets;
        std::uint64_t scannedTo = 0; // the next search goes on from here (a followed file)
        bool full = false;           // `limit` reached: the search stopped there
    };
    // Searches the finished lines of `data` past m.scannedTo (up to completeEnd()). A line's
    // address is what a sentence has between '$' or '!' and the first ',' or '*' ("" for a line
    // that is no sentence). False when cancelled (m keeps what was found until then).
    bool findLines(std::string_view data, const std::function<bool(std::string_view)> &keep,
                   std::size_t limit, Matches &m, const std::atomic<bool> *cancel = nullptr) const;
    static std::string_view addressOf(std::string_view line);

private:
    std::vector<std::uint64_t> starts_; // starts_[i]: where line i × kStride starts
    std::uint64_t complete_ = 0;        // lines ended by '\n' or by the length cut
    std::uint64_t end_ = 0;             // where the line after them starts
    std::uint64_t scanned_ = 0;
    bool openLine_ = false; // bytes after end_ make an unfinished last line
};

} // namespace gnss::logview
