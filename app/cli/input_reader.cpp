#include "input_reader.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

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

} // namespace gnss::cli
