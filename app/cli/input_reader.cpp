#include "cli/input_reader.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gnss::cli {

bool readInput(const std::string &path, FunctionRef<void(std::string_view)> onChunk,
               std::string &error) {
    const bool useStdin = path.empty() || path == "-";
    std::FILE *f = useStdin ? stdin : std::fopen(path.c_str(), "rb");
    if (!f) {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    constexpr std::size_t kChunk = 1 << 20;
    std::unique_ptr<char[]> buf(new char[kChunk]);
    bool ok = true;
    while (true) {
        const std::size_t n = std::fread(buf.get(), 1, kChunk, f);
        if (n > 0) onChunk(std::string_view(buf.get(), n));
        if (n < kChunk) {
            if (std::ferror(f)) {
                error = (useStdin ? std::string("stdin") : path) + ": read error";
                ok = false;
            }
            break;
        }
    }
    if (!useStdin) std::fclose(f);
    return ok;
}

MappedFile::MappedFile(const std::string &path) {
    if (path.empty() || path == "-") return;
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) {
        error_ = path + ": " + std::strerror(errno);
        return;
    }
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
        size_ = static_cast<std::size_t>(st.st_size);
        if (size_ == 0) {
            mappedEmpty_ = true;
        } else {
            void *p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
            if (p == MAP_FAILED) {
                size_ = 0;
            } else {
                data_ = p;
                ::madvise(p, size_, MADV_SEQUENTIAL);
            }
        }
    }
    ::close(fd);
}

MappedFile::~MappedFile() {
    if (data_) ::munmap(data_, size_);
}

} // namespace gnss::cli
