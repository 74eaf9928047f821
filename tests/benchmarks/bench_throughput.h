#pragma once
// What the decoder benchmarks share: the input fed in 1 MiB chunks (as a file reader hands it
// over), and the throughput counters they print.
#include <cstddef>
#include <cstdint>
#include <string_view>

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
