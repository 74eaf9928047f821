#pragma once
// What the decoder benchmarks share: the input fed in 1 MiB chunks (as a file reader hands it
// over), and the throughput counters they print.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include <benchmark/benchmark.h>

namespace gnss::bench {

constexpr std::size_t kChunk = 1 << 20;

// feed(chunk) for each 1 MiB piece of `data`, in order.
template <class Feed> void feedInChunks(std::string_view data, Feed &&feed) {
    for (std::size_t pos = 0; pos < data.size(); pos += kChunk) feed(data.substr(pos, kChunk));
}

// Each iteration went through `bytes` of input: bytes processed and MB/s.
inline void reportBytes(benchmark::State &state, std::size_t bytes) {
    const double total = static_cast<double>(state.iterations()) * static_cast<double>(bytes);
    state.SetBytesProcessed(static_cast<std::int64_t>(total));
    state.counters["MB/s"] = benchmark::Counter(total / 1e6, benchmark::Counter::kIsRate);
}

// `count` things (sentences, frames) over all iterations, as a rate named `name`.
inline void reportRate(benchmark::State &state, const char *name, std::uint64_t count) {
    state.counters[name] =
            benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsRate);
}

} // namespace gnss::bench

namespace gnss::bench {

// The console output, and at the end one line per benchmark run more than once
// (->Repetitions(n)): the best and the median of its MB/s over the runs. This machine's speed
// swings by a fifth from minute to minute (a shared host); nothing but other load makes a run
// slower than the code is, so the best run is the figure the code earns, and the median shows
// how much the others took away.
class BestOfReporter : public benchmark::ConsoleReporter {
public:
    // As the library's own console output: colours on a terminal, plain "name=value" counters
    // otherwise (what scripts read).
    BestOfReporter() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_Color : OO_None) {}

    void ReportRuns(const std::vector<Run> &runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run &r : runs) {
            if (r.run_type != Run::RT_Iteration || r.repetitions < 2) continue;
            const auto c = r.counters.find("MB/s");
            if (c != r.counters.end()) rates_[r.run_name.function_name].push_back(c->second.value);
        }
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        for (auto &[name, v] : rates_) {
            std::sort(v.begin(), v.end());
            std::printf("%s: best %.0f MB/s, median %.0f MB/s (%zu runs)\n", name.c_str(), v.back(),
                        v[v.size() / 2], v.size());
        }
    }

private:
    std::map<std::string, std::vector<double>> rates_;
};

// main() of a benchmark program whose figures are summarised so.
inline int runWithBestOf(int argc, char **argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    BestOfReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}

} // namespace gnss::bench
