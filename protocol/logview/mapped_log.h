#pragma once
// MappedLog: a log file memory-mapped read-only, with 64-bit offsets, that can follow a file
// still being written and notices one truncated under it.
//
// The mapping reserves address space well past the file's end, so a growing file is followed
// without moving the mapping: views handed out stay valid. Bytes are only ever read below the
// size last checked (refresh()), so a file truncated while open is reported, not a crash (short
// of it being cut in the very instant between the check and the read).
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace gnss::logview {

class MappedLog {
public:
    MappedLog() = default;
    ~MappedLog();
    MappedLog(const MappedLog &) = delete;
    MappedLog &operator=(const MappedLog &) = delete;

    // Maps `path`; false with error() set when it cannot be opened or mapped. An empty file maps.
    bool open(const std::string &path);
    // Maps a file descriptor already open (the temporary file a .gz log is inflated to); takes
    // ownership. `name` is used in messages.
    bool adopt(int fd, const std::string &name);
    void close();

    bool isOpen() const { return fd_ >= 0; }
    const std::string &error() const { return error_; }
    const std::string &path() const { return path_; }

    // The size when last checked.
    std::uint64_t size() const { return size_; }
    // Re-reads the file's size: grown (the new bytes become readable), unchanged, or shrunk
    // (truncated: size() becomes the new size; what was read from beyond it must be dropped).
    enum class Change { Unchanged, Grown, Shrunk, Gone };
    Change refresh();
    // The file's size right now (without taking it: min(now, size())); 0 when unknown.
    std::uint64_t liveSize() const;

    // [offset, offset + length) clipped to size(); empty past the end.
    std::string_view bytes(std::uint64_t offset, std::uint64_t length) const;
    std::string_view all() const { return bytes(0, size_); }
    const char *base() const { return static_cast<const char *>(map_); }

private:
    bool mapFd(int fd);

    int fd_ = -1;
    void *map_ = nullptr;
    std::uint64_t mapLength_ = 0; // address space reserved (>= size_)
    std::uint64_t size_ = 0;
    std::string path_, error_;
};

// Whether `bytes` start like a gzip stream (1F 8B).
bool looksGzipped(std::string_view bytes);

// Inflates the gzip file `path` (all its members, as gzip -d does) into an unnamed temporary file
// (in $TMPDIR, or /tmp) and returns its descriptor, or -1 with `error` set (cancelled: error
// empty). A stream broken part way returns what came before it, with `error` saying so.
// `progress` (0..1) and `cancel` are polled every megabyte.
int inflateToTemporary(const std::string &path, std::string &error,
                       const std::atomic<bool> *cancel = nullptr,
                       std::atomic<double> *progress = nullptr);

// The parts of it: an unnamed temporary file (its descriptor, or -1 with `error` set) ...
int createTemporaryFile(std::string &error);
// ... and the inflating into `out` (at its current position; not closed). False when cancelled
// (error empty) or when nothing could be read or written (error set); a stream broken part way
// is true, with `error` saying so. `written` (when set) hears the bytes written so far after
// every megabyte, from the calling thread.
bool inflateInto(const std::string &path, int out, std::string &error,
                 const std::atomic<bool> *cancel = nullptr, std::atomic<double> *progress = nullptr,
                 const std::function<void(std::uint64_t)> &written = {});

} // namespace gnss::logview
