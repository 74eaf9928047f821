// gnss-loggen FILE [MEGABYTES]: writes the benchmark's generated 10 Hz log (default 120 MB).
#include "log_generator.h"

#include <cstdio>
#include <cstdlib>
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
    const std::size_t mb = argc > 2 ? std::strtoul(argv[2], &end, 10) : 120;
    // A FILE that looks like an option, a size that is no number or zero, extra arguments: no
    // file is written.
    if (argc < 2 || argc > 3 || argv[1][0] == '-' || mb == 0 || (end && *end)) {
        std::fputs(usage, stderr);
        return 2;
    }
    std::string log;
    log.reserve(mb * 1000000 + 4096);
    gnss::bench::generateLog(log, mb * 1000000);
    std::FILE *f = std::fopen(argv[1], "wb");
    if (!f || std::fwrite(log.data(), 1, log.size(), f) != log.size()) {
        std::fprintf(stderr, "gnss-loggen: cannot write %s\n", argv[1]);
        return 1;
    }
    std::fclose(f);
    std::printf("%s: %zu bytes\n", argv[1], log.size());
    return 0;
}
