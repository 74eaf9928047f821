// The log viewer's engine on a big log: prints (does not assert) how long indexing takes beside
// a checksum-only pass of the same file, when the first epoch is available, how long seeks to
// random epochs take, and the memory used beyond the mapped file.
//
//   bench_logview [FILE] [--threads N] [--seeks N] [--keep]
//
// Without FILE it writes gnss-loggen's 10 Hz multi-constellation log of 1 GB to $TMPDIR (in a
// child process, so that its memory is not counted here) and deletes it at the end.
#include "builtin/dialects.h"
#include "core/framer.h"
#include "core/sentence.h"
#include "log_generator.h"
#include "logview/log_view.h"
#include "state/log_scan.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Framing and checksums only, on the same pieces and threads as the index.
std::uint64_t checksumPass(std::string_view log, unsigned threads) {
    const auto pieces = gnss::cutLog(log, threads);
    std::vector<std::uint64_t> ok(pieces.size());
    auto work = [&](std::size_t k) {
        gnss::Framer framer;
        std::uint64_t n = 0;
        framer.feed(pieces[k], [&](std::string_view line) {
            gnss::Sentence s;
            if (s.parse(line) && s.checksum() == gnss::ChecksumStatus::Ok) ++n;
        });
        ok[k] = n;
    };
    gnss::runPieces(pieces.size(), threads, work);
    std::uint64_t total = 0;
    for (auto n : ok) total += n;
    return total;
}

} // namespace

int main(int argc, char **argv) {
    std::string path;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    int seeks = 1000;
    bool keep = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--threads" && i + 1 < argc)
            threads = static_cast<unsigned>(std::atoi(argv[++i]));
        else if (a == "--seeks" && i + 1 < argc)
            seeks = std::atoi(argv[++i]);
        else if (a == "--keep")
            keep = true;
        else if (a.empty() || a[0] == '-' || !path.empty()) {
            std::fprintf(a == "--help" ? stdout : stderr,
                         "usage: bench_logview [FILE] [--threads N] [--seeks N] [--keep]\n");
            return a == "--help" ? 0 : 2;
        } else
            path = a;
    }
    bool generated = false;
    if (path.empty()) {
        const char *tmp = std::getenv("TMPDIR");
        path = std::string(tmp && *tmp ? tmp : "/tmp") + "/bench_logview_1GB.nmea";
        std::printf("generating %s (1 GB, 10 Hz, GPS+GLONASS+Galileo+BeiDou)...\n", path.c_str());
        std::fflush(stdout);
        const auto t0 = Clock::now();
        if (!gnss::bench::writeLogFile(path, 1'000'000'000)) {
            std::fprintf(stderr, "cannot write %s\n", path.c_str());
            return 1;
        }
        std::printf("  written in %.1f s\n", since(t0));
        generated = true;
    }
    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    struct stat st {};
    ::stat(path.c_str(), &st);
    const double mb = static_cast<double>(st.st_size) / 1e6;
    std::printf("log: %s, %.0f MB; %u threads\n", path.c_str(), mb, threads);

    // Checksum-only pass over the same mapping (pages warm, as the index will find them).
    {
        const int fd = ::open(path.c_str(), O_RDONLY);
        void *p =
                ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_SHARED, fd, 0);
        const std::string_view log(static_cast<const char *>(p),
                                   static_cast<std::size_t>(st.st_size));
        checksumPass(log, threads); // warm-up: page cache and mapping
        const auto t0 = Clock::now();
        const std::uint64_t n = checksumPass(log, threads);
        const double s = since(t0);
        std::printf("checksum-only pass:      %6.3f s  (%5.0f MB/s, %llu sentences)\n", s, mb / s,
                    static_cast<unsigned long long>(n));
        ::munmap(p, static_cast<std::size_t>(st.st_size));
        ::close(fd);
    }

    const long anonBefore = gnss::bench::statusKb("RssAnon:");
    gnss::logview::LogViewOptions options;
    options.index.threads = threads;
    gnss::logview::LogView view(registry, options);
    const auto t0 = Clock::now();
    view.open(path);
    double firstAt = -1;
    while (!view.waitUntilIndexed(0)) {
        if (firstAt < 0 && view.firstEpoch()) firstAt = since(t0);
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    const double indexed = since(t0);
    if (firstAt < 0) firstAt = indexed;
    if (view.progress().phase != gnss::logview::LogView::Phase::Ready) {
        std::fprintf(stderr, "index failed: %s\n", view.error().c_str());
        return 1;
    }
    const long anonAfter = gnss::bench::statusKb("RssAnon:");
    const std::size_t epochs = view.epochCount();
    std::printf("index complete:          %6.3f s  (%5.0f MB/s, %zu epochs, %zu events)\n", indexed,
                mb / indexed, epochs, view.events().size());
    std::printf("first epoch available:   %6.3f s after open\n", firstAt);

    std::mt19937_64 rng(42);
    std::vector<double> ms;
    gnss::ReceiverState state;
    for (int i = 0; i < seeks && epochs > 0; ++i) {
        const std::size_t k = rng() % epochs;
        const auto s0 = Clock::now();
        if (!view.stateAt(k, state)) {
            std::fprintf(stderr, "seek to %zu failed\n", k);
            return 1;
        }
        ms.push_back(since(s0) * 1000);
    }
    std::sort(ms.begin(), ms.end());
    if (!ms.empty())
        std::printf("seek to a random epoch:  median %.2f ms, 99th percentile %.2f ms, max %.2f "
                    "ms (%zu seeks)\n",
                    ms[ms.size() / 2], ms[ms.size() * 99 / 100], ms.back(), ms.size());
    // The console's virtual list over the file: the lines counted once (on a worker in the GUI),
    // then any line read from the mapping as it is drawn.
    const auto l0 = Clock::now();
    const std::uint64_t lines = view.indexLines();
    std::printf("console lines counted:   %6.3f s  (%llu lines)\n", since(l0),
                static_cast<unsigned long long>(lines));
    std::vector<double> us;
    for (int i = 0; i < 10000 && lines > 0; ++i) {
        const std::uint64_t k = rng() % lines;
        const auto s0 = Clock::now();
        if (!view.line(k)) {
            std::fprintf(stderr, "line %llu not found\n", static_cast<unsigned long long>(k));
            return 1;
        }
        us.push_back(since(s0) * 1e6);
    }
    std::sort(us.begin(), us.end());
    if (!us.empty())
        std::printf("console line at random:  median %.1f us, 99th percentile %.1f us\n",
                    us[us.size() / 2], us[us.size() * 99 / 100]);
    const double recordsMb = static_cast<double>(epochs * sizeof(gnss::logview::EpochRecord)) / 1e6;
    std::printf("memory beyond the mapped file: %.0f MB anonymous (the index's records %.0f MB "
                "of it; checkpoints and the rest %.0f MB); file pages mapped: %ld MB\n",
                static_cast<double>(anonAfter - anonBefore) / 1024, recordsMb,
                static_cast<double>(anonAfter - anonBefore) / 1024 - recordsMb,
                gnss::bench::statusKb("RssFile:") / 1024);
    if (generated && !keep) {
        ::unlink(path.c_str());
        std::printf("deleted %s\n", path.c_str());
    }
    return 0;
}
