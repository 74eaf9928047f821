#pragma once
// HostTimes: the host clock of a recording made by this tool (docs/recording.md): FILE.idx says
// when each chunk of FILE arrived, and where the link was lost and came back. Read without Qt,
// tolerant as loadRecording is (a torn last line is ignored; bytes past the last chunk take its
// time); an index that contradicts the file is reported and not used.
#include <cstdint>
#include <string>
#include <vector>

namespace gnss::logview {

struct HostChunk {
    std::uint64_t offset = 0;
    std::int64_t hostMs = 0; // ms since 1970-01-01 UTC, host clock
};

struct LinkGap {
    std::uint64_t offset = 0; // bytes received before it
    std::int64_t hostMs = 0;
    std::string text; // "link lost: ..." / "link back: ..."
};

class HostTimes {
public:
    // Reads `indexPath` for a data file of `dataSize` bytes. False (and nothing kept) when the
    // file is absent (error() empty) or unusable (error() says why).
    bool load(const std::string &indexPath, std::uint64_t dataSize);
    bool empty() const { return chunks_.empty(); }
    const std::string &error() const { return error_; }
    // Host time of the byte at `offset` (the chunk it arrived in); kNoTime-like INT64_MIN when
    // there is no index.
    std::int64_t at(std::uint64_t offset) const;
    const std::vector<LinkGap> &gaps() const { return gaps_; }

private:
    std::vector<HostChunk> chunks_;
    std::vector<LinkGap> gaps_;
    std::string error_;
};

} // namespace gnss::logview
