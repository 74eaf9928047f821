// Decoder throughput on a generated 10 Hz multi-constellation log of at least 100 MB: a full
// decode (framer, checksum, every field of every sentence, epoch assembly) against a
// checksum-only pass. Prints MB/s and sentences/s; the full decode on one core and on every
// core runs five times, and the last lines give the best and the median of each.
#include "bench_throughput.h"
#include "log_generator.h"

#include "builtin/dialects.h"
#include "core/framer.h"
#include "core/sentence.h"
#include "core/stream_decoder.h"
#include "state/epoch_assembler.h"
#include "state/log_scan.h"

#include <thread>

#include <benchmark/benchmark.h>

namespace {

const std::string &log100MB() {
    static const std::string log = [] {
        std::string s;
        s.reserve(105'000'000);
        gnss::bench::generateLog(s, 100'000'000);
        return s;
    }();
    return log;
}

using gnss::bench::feedInChunks;
using gnss::bench::reportBytes;
using gnss::bench::reportRate;

void BM_FullDecode(benchmark::State &state) {
    const std::string &log = log100MB();
    const gnss::DialectRegistry reg = gnss::makeBuiltinRegistry();
    std::uint64_t sentences = 0, epochs = 0;
    for (auto _ : state) {
        gnss::StreamDecoder dec(reg);
        gnss::EpochAssembler assembler;
        auto onEpoch = [&](const gnss::Epoch &) { ++epochs; };
        auto onSentence = [&](const gnss::SentenceEvent &ev) {
            ++sentences;
            if (ev.message) assembler.add(ev.sentence, *ev.message, onEpoch);
        };
        feedInChunks(log, [&](std::string_view chunk) { dec.feed(chunk, onSentence); });
        dec.finish();
        assembler.flush(onEpoch);
    }
    reportBytes(state, log.size());
    reportRate(state, "sentences/s", sentences);
    state.counters["log_MB"] = static_cast<double>(log.size()) / 1e6;
}
BENCHMARK(BM_FullDecode)
        ->Unit(benchmark::kMillisecond)
        ->MinTime(2.0)
        ->UseRealTime()
        ->Repetitions(5);

// The same full decode on every core (what `gnss-cli stats` does with a file): scanLog cuts the
// log at line ends and merges the counts exactly.
void BM_FullDecodeAllCores(benchmark::State &state) {
    const std::string &log = log100MB();
    const gnss::DialectRegistry reg = gnss::makeBuiltinRegistry();
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::uint64_t sentences = 0;
    for (auto _ : state) {
        const gnss::LogScanResult r = gnss::scanLog(log, reg, {}, threads);
        sentences += r.framer.sentences;
    }
    reportBytes(state, log.size());
    reportRate(state, "sentences/s", sentences);
    state.counters["threads"] = threads;
}
BENCHMARK(BM_FullDecodeAllCores)
        ->Unit(benchmark::kMillisecond)
        ->MinTime(2.0)
        ->UseRealTime()
        ->Repetitions(5);

// Stages, to see where the time goes: framing + sentence parsing (checksum, field split), and
// the full decode without epoch assembly.
void BM_FrameAndParse(benchmark::State &state) {
    const std::string &log = log100MB();
    std::uint64_t fields = 0;
    for (auto _ : state) {
        gnss::Framer framer;
        auto onLine = [&](std::string_view line) {
            gnss::Sentence s;
            if (s.parse(line)) fields += s.fieldCount();
        };
        feedInChunks(log, [&](std::string_view chunk) { framer.feed(chunk, onLine); });
    }
    benchmark::DoNotOptimize(fields);
    reportBytes(state, log.size());
}
BENCHMARK(BM_FrameAndParse)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

void BM_DecodeWithoutEpochs(benchmark::State &state) {
    const std::string &log = log100MB();
    const gnss::DialectRegistry reg = gnss::makeBuiltinRegistry();
    std::uint64_t decoded = 0;
    for (auto _ : state) {
        gnss::StreamDecoder dec(reg);
        auto onSentence = [&](const gnss::SentenceEvent &ev) { decoded += ev.message != nullptr; };
        feedInChunks(log, [&](std::string_view chunk) { dec.feed(chunk, onSentence); });
    }
    benchmark::DoNotOptimize(decoded);
    reportBytes(state, log.size());
}
BENCHMARK(BM_DecodeWithoutEpochs)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

void BM_ChecksumOnly(benchmark::State &state) {
    const std::string &log = log100MB();
    std::uint64_t sentences = 0, ok = 0;
    for (auto _ : state) {
        gnss::Framer framer;
        auto onLine = [&](std::string_view line) {
            ++sentences;
            const auto star = line.rfind('*');
            if (star != std::string_view::npos && gnss::nmeaChecksum(line.substr(1, star - 1)) != 0)
                ++ok;
        };
        feedInChunks(log, [&](std::string_view chunk) { framer.feed(chunk, onLine); });
    }
    benchmark::DoNotOptimize(ok);
    reportBytes(state, log.size());
    reportRate(state, "sentences/s", sentences);
}
BENCHMARK(BM_ChecksumOnly)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

} // namespace

int main(int argc, char **argv) {
    return gnss::bench::runWithBestOf(argc, argv);
}
