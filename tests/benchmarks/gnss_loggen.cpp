// gnss-loggen FILE [MEGABYTES]: writes the benchmark's generated 10 Hz log (default 120 MB).
#include "log_generator.h"

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char **argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: gnss-loggen FILE [MEGABYTES]\n");
        return 2;
    }
    const std::size_t mb = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 120;
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
