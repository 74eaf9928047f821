// gnss-loggen FILE [MEGABYTES]: writes the benchmark's generated 10 Hz log (default 120 MB).
#include "log_generator.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char **argv) {
    const char *usage = "usage: gnss-loggen FILE [MEGABYTES]\n"
                        "Writes the benchmarks' generated 10 Hz multi-constellation log (default "
                        "120 MB).\n";
    if (argc == 2 && std::string(argv[1]) == "--help") {
        std::fputs(usage, stdout);
        return 0;
    }
    char *end = nullptr;
    errno = 0;
    const unsigned long long mb = argc > 2 ? std::strtoull(argv[2], &end, 10) : 120;
    // A FILE that looks like an option, a size that is no number, zero or more than a terabyte,
    // extra arguments: no file is written.
    if (argc < 2 || argc > 3 || argv[1][0] == '-' || mb == 0 || mb > 1000000 || errno ||
        (end && *end) || (argc > 2 && argv[2][0] == '-')) {
        std::fputs(usage, stderr);
        return 2;
    }
    // Written a few megabytes at a time: a log of any size takes no more memory than that.
    const std::uint64_t want = mb * 1000000ull;
    std::FILE *f = std::fopen(argv[1], "wb");
    gnss::bench::LogGenerator generator;
    std::string piece;
    std::uint64_t written = 0;
    while (f && written < want) {
        piece.clear();
        generator.append(
                piece, static_cast<std::size_t>(std::min<std::uint64_t>(4 << 20, want - written)));
        if (std::fwrite(piece.data(), 1, piece.size(), f) != piece.size()) break;
        written += piece.size();
    }
    if (!f || written < want || std::fclose(f) != 0) {
        std::fprintf(stderr, "gnss-loggen: cannot write %s: %s\n", argv[1], std::strerror(errno));
        return 1;
    }
    std::printf("%s: %llu bytes\n", argv[1], static_cast<unsigned long long>(written));
    return 0;
}
