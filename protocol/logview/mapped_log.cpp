#include "logview/mapped_log.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

namespace gnss::logview {
namespace {

// Address space reserved past the end of a file, for following it as it grows (no memory is
// used for it: pages exist only where the file does).
constexpr std::uint64_t kGrowthReserve = std::uint64_t(64) << 30;

std::string errnoText() {
    return std::strerror(errno);
}

} // namespace

MappedLog::~MappedLog() {
    close();
}

void MappedLog::close() {
    if (map_) ::munmap(map_, mapLength_);
    if (fd_ >= 0) ::close(fd_);
    map_ = nullptr;
    fd_ = -1;
    mapLength_ = size_ = 0;
}

bool MappedLog::open(const std::string &path) {
    close();
    path_ = path;
    error_.clear();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        error_ = path + ": " + errnoText();
        return false;
    }
    return mapFd(fd);
}

bool MappedLog::adopt(int fd, const std::string &name) {
    close();
    path_ = name;
    error_.clear();
    return mapFd(fd);
}

bool MappedLog::mapFd(int fd) {
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        error_ = path_ + ": " + errnoText();
        ::close(fd);
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        error_ = path_ + ": not a regular file";
        ::close(fd);
        return false;
    }
    fd_ = fd;
    size_ = static_cast<std::uint64_t>(st.st_size);
    const long page = ::sysconf(_SC_PAGESIZE);
    mapLength_ = (size_ + kGrowthReserve + page - 1) / page * page;
    void *p = ::mmap(nullptr, mapLength_, PROT_READ, MAP_SHARED | MAP_NORESERVE, fd_, 0);
    if (p == MAP_FAILED) {
        // Without the reserve (address space limited by ulimit -v): the file as it is.
        mapLength_ = std::max<std::uint64_t>(size_, 1);
        p = ::mmap(nullptr, mapLength_, PROT_READ, MAP_SHARED, fd_, 0);
    }
    if (p == MAP_FAILED) {
        error_ = path_ + ": cannot map: " + errnoText();
        ::close(fd_);
        fd_ = -1;
        size_ = mapLength_ = 0;
        return false;
    }
    map_ = p;
    return true;
}

MappedLog::Change MappedLog::refresh() {
    if (fd_ < 0) return Change::Gone;
    struct stat st {};
    if (::fstat(fd_, &st) != 0) return Change::Gone;
    const auto now = static_cast<std::uint64_t>(st.st_size);
    if (now == size_) return st.st_nlink == 0 ? Change::Gone : Change::Unchanged;
    if (now < size_) {
        size_ = now;
        return Change::Shrunk;
    }
    // Grown: readable up to the reserve (a file grown past it would need a new mapping).
    size_ = std::min(now, mapLength_);
    return Change::Grown;
}

std::uint64_t MappedLog::liveSize() const {
    struct stat st {};
    if (fd_ < 0 || ::fstat(fd_, &st) != 0) return 0;
    return std::min(static_cast<std::uint64_t>(st.st_size), size_);
}

std::string_view MappedLog::bytes(std::uint64_t offset, std::uint64_t length) const {
    if (!map_ || offset >= size_) return {};
    length = std::min(length, size_ - offset);
    return {static_cast<const char *>(map_) + offset, static_cast<std::size_t>(length)};
}

bool looksGzipped(std::string_view b) {
    return b.size() >= 2 && static_cast<unsigned char>(b[0]) == 0x1F &&
           static_cast<unsigned char>(b[1]) == 0x8B;
}

int createTemporaryFile(std::string &error) {
    const char *tmp = std::getenv("TMPDIR");
    std::string dir = tmp && *tmp ? tmp : "/tmp";
    // Unnamed: the inflated copy disappears with the descriptor, whatever happens.
    int out = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (out < 0) {
        std::string name = dir + "/gnss-logview-XXXXXX";
        out = ::mkstemp(name.data());
        if (out >= 0) ::unlink(name.c_str());
    }
    if (out < 0) error = "cannot create a temporary file in " + dir + ": " + errnoText();
    return out;
}

bool inflateInto(const std::string &path, int out, std::string &error,
                 const std::atomic<bool> *cancel, std::atomic<double> *progress,
                 const std::function<void(std::uint64_t)> &written) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        error = path + ": " + errnoText();
        return false;
    }
    const int in = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) {
        error = path + ": " + errnoText();
        return false;
    }
    gzFile gz = ::gzdopen(in, "rb");
    if (!gz) {
        ::close(in);
        error = path + ": cannot read as gzip";
        return false;
    }
    ::gzbuffer(gz, 1 << 20);
    std::string buf(1 << 20, '\0');
    std::uint64_t total = 0;
    bool ok = true;
    while (true) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            error.clear();
            ok = false;
            break;
        }
        const int n = ::gzread(gz, buf.data(), static_cast<unsigned>(buf.size()));
        if (n < 0) {
            int code = 0;
            const char *msg = ::gzerror(gz, &code);
            error = path + ": " + (msg ? msg : "gzip data broken") +
                    " (the part before it is kept)";
            break; // keep what was inflated: a truncated .gz is still a log
        }
        if (n == 0) {
            int code = Z_OK;
            const char *msg = ::gzerror(gz, &code);
            if (code != Z_OK && code != Z_STREAM_END)
                error = path + ": " + (msg && *msg ? msg : "gzip data broken") +
                        " (the part before it is kept)";
            break;
        }
        for (std::size_t done = 0; done < static_cast<std::size_t>(n);) {
            const ssize_t w = ::write(out, buf.data() + done, static_cast<std::size_t>(n) - done);
            if (w <= 0) {
                error = "cannot write the inflated log: " + errnoText();
                ok = false;
                break;
            }
            done += static_cast<std::size_t>(w);
        }
        if (!ok) break;
        total += static_cast<std::uint64_t>(n);
        if (progress && st.st_size > 0)
            progress->store(std::min(1.0, static_cast<double>(::gzoffset(gz)) /
                                                  static_cast<double>(st.st_size)));
        if (written) written(total);
    }
    ::gzclose(gz);
    return ok;
}

int inflateToTemporary(const std::string &path, std::string &error, const std::atomic<bool> *cancel,
                       std::atomic<double> *progress) {
    const int out = createTemporaryFile(error);
    if (out < 0) return -1;
    if (!inflateInto(path, out, error, cancel, progress)) {
        ::close(out);
        return -1;
    }
    return out;
}

} // namespace gnss::logview
