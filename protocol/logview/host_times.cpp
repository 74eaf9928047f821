#include "logview/host_times.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <limits>

namespace gnss::logview {
namespace {

bool number(std::string_view s, std::int64_t &out) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// The next space-separated word of `line`, from `pos`.
std::string_view word(std::string_view line, std::size_t &pos) {
    const std::size_t start = pos;
    pos = line.find(' ', start);
    if (pos == std::string_view::npos) pos = line.size();
    std::string_view w = line.substr(start, pos - start);
    if (pos < line.size()) ++pos;
    return w;
}

} // namespace

bool HostTimes::load(const std::string &indexPath, std::uint64_t dataSize) {
    chunks_.clear();
    gaps_.clear();
    error_.clear();
    std::ifstream in(indexPath, std::ios::binary);
    if (!in) return false;
    std::string line;
    std::uint64_t expected = 0, lastOffset = 0;
    std::int64_t lastMs = 0;
    int lineNo = 0;
    auto bad = [&](const std::string &why) {
        error_ = indexPath + ", line " + std::to_string(lineNo) + ": " + why +
                 " (host times not used)";
        chunks_.clear();
        gaps_.clear();
        return false;
    };
    while (std::getline(in, line)) {
        ++lineNo;
        if (in.eof()) break; // a torn last line (no '\n'): the recorder stopped mid-write
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        std::size_t pos = 0;
        const std::string_view kind = word(line, pos);
        std::int64_t ms = 0, offset = 0;
        if (kind.size() != 1 || !number(word(line, pos), ms) || !number(word(line, pos), offset) ||
            offset < 0)
            return bad("not an index line");
        // Before 1970 is no clock reading (and differences of host times must not overflow).
        if (ms < 0) return bad("bad host time");
        // Records are written as the bytes arrive: their offsets never go back, nor past the data.
        const auto at = static_cast<std::uint64_t>(offset);
        if (at < lastOffset)
            return bad("offset " + std::to_string(at) + " is before the previous record's " +
                       std::to_string(lastOffset));
        if (at > dataSize) return bad("offset past the end of the data file");
        lastOffset = at;
        if (kind[0] == 'R') {
            std::int64_t length = 0;
            if (!number(word(line, pos), length) || length < 0) return bad("bad length");
            if (static_cast<std::uint64_t>(offset) != expected)
                return bad("chunk starts at " + std::to_string(offset) + ", expected " +
                           std::to_string(expected));
            // offset == expected <= dataSize here: the difference cannot wrap.
            if (static_cast<std::uint64_t>(length) > dataSize - expected)
                return bad("chunk ends past the end of the data file");
            if (length > 0) chunks_.push_back({static_cast<std::uint64_t>(offset), ms});
            expected = static_cast<std::uint64_t>(offset + length);
        } else if (kind[0] == 'G') {
            gaps_.push_back({static_cast<std::uint64_t>(offset), ms,
                             std::string(std::string_view(line).substr(pos))});
        } else if (kind[0] != 'S') {
            return bad("unknown record '" + std::string(kind) + "'");
        }
        lastMs = ms;
    }
    // Bytes after the last indexed chunk arrived at the last known time.
    if (expected < dataSize) chunks_.push_back({expected, lastMs});
    return !chunks_.empty();
}

std::int64_t HostTimes::at(std::uint64_t offset) const {
    if (chunks_.empty()) return std::numeric_limits<std::int64_t>::min();
    auto it = std::upper_bound(chunks_.begin(), chunks_.end(), offset,
                               [](std::uint64_t o, const HostChunk &c) { return o < c.offset; });
    if (it == chunks_.begin()) return chunks_.front().hostMs;
    return std::prev(it)->hostMs;
}

} // namespace gnss::logview
