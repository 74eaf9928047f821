// RTCM 3 throughput on a generated base-station stream of at least 50 MB (1 Hz MSM7 for GPS,
// GLONASS, Galileo and BeiDou; 1005, 1033 and 1230 every 10 s; ephemerides now and then): framing
// alone, framing + decoding, and framing + decoding + JSON (what `gnss-cli rtcm` does). Prints
// MB/s.
#include "bench_throughput.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm/rtcm_json.h"
#include "rtcm/rtcm_stream_decoder.h"

#include <bit>
#include <random>

#include <benchmark/benchmark.h>

namespace {

using namespace gnss::rtcm;

std::uint64_t firstSatellites(unsigned n, unsigned skip) {
    std::uint64_t m = 0;
    for (unsigned i = 0; i < n; ++i) m |= std::uint64_t(1) << (63 - (i * skip) % 40);
    return m;
}

std::string epoch(std::uint32_t second, std::mt19937 &rng) {
    std::string s;
    struct Constellation {
        System system;
        unsigned satellites;
        std::uint32_t signals;
    };
    // Signal masks: GPS 1C 2S 2L 5Q, GLONASS 1C 2C, Galileo 1C 7Q 5I, BeiDou 2I 6Q 7Q.
    constexpr Constellation kSky[] = {{System::Gps, 10, 0x40030200},
                                      {System::Glonass, 8, 0x41000000},
                                      {System::Galileo, 8, 0x40020400},
                                      {System::BeiDou, 10, 0x40820000}};
    for (const Constellation &c : kSky) {
        MsmHeader h;
        h.system = c.system;
        h.msmType = 7;
        h.station = 2003;
        h.epochMs = second * 1000;
        if (c.system == System::Glonass) h.gloDayOfWeek = 1;
        h.multipleMessage = c.system != System::BeiDou;
        h.satelliteMask = firstSatellites(c.satellites, 1 + rng() % 3);
        h.signalMask = c.signals;
        const unsigned cells =
                unsigned(std::popcount(h.satelliteMask) * std::popcount(h.signalMask));
        h.cellMask = (cells == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << cells) - 1) &
                     ~(std::uint64_t(rng()) & 0x2101); // a few signals missing
        s += encodeMsm(h);
    }
    if (second % 10 == 0) {
        StationArp a;
        a.station = 2003;
        a.gps = a.glonass = a.galileo = true;
        a.x = 2849878.1521;
        a.y = 2195934.8381;
        a.z = 5249094.9248;
        s += encodeStationArp(a);
        AntennaInfo info;
        info.station = 2003;
        info.antennaDescriptor = "TRM57971.00     NONE";
        info.antennaSerial = "1441031520";
        info.receiverType = "GNSS WORKBENCH SIM";
        info.firmware = "0.1.0";
        info.receiverSerial = "0001";
        s += encodeAntennaInfo(1033, info);
        GlonassBiases b;
        b.station = 2003;
        b.present = {true, true, true, true};
        b.biases = {1.0, 1.0, 1.0, 1.0};
        s += encodeGlonassBiases(b);
    }
    if (second % 5 == 0) {
        Ephemeris e;
        e.satellite = 1 + second % 32;
        e.week = 300;
        e.iode = second % 256;
        s += encodeEphemeris(1019, e);
        e.satellite = 1 + second % 36;
        s += encodeEphemeris(1046, e);
    }
    return s;
}

const std::string &stream50MB() {
    static const std::string s = [] {
        // One hour of distinct epochs, repeated until 50 MB (encoding is bit by bit: not the
        // point of this benchmark).
        std::mt19937 rng(1);
        std::string hour;
        for (std::uint32_t sec = 0; sec < 3600; ++sec) hour += epoch(sec, rng);
        std::string out;
        out.reserve(52'000'000);
        while (out.size() < 50'000'000) out += hour;
        return out;
    }();
    return s;
}

using gnss::bench::feedInChunks;

void report(benchmark::State &state, std::size_t bytes, std::uint64_t frames) {
    gnss::bench::reportBytes(state, bytes);
    gnss::bench::reportRate(state, "frames/s", frames);
    state.counters["stream_MB"] = static_cast<double>(bytes) / 1e6;
}

void BM_RtcmFrameOnly(benchmark::State &state) {
    const std::string &s = stream50MB();
    std::uint64_t frames = 0;
    for (auto _ : state) {
        RtcmFramer f;
        auto onFrame = [&](const RtcmFrame &) { ++frames; };
        feedInChunks(s, [&](std::string_view chunk) { f.feed(chunk, onFrame); });
        f.finish(onFrame);
    }
    report(state, s.size(), frames);
}
BENCHMARK(BM_RtcmFrameOnly)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

void BM_RtcmFrameAndDecode(benchmark::State &state) {
    const std::string &s = stream50MB();
    std::uint64_t frames = 0, satellites = 0;
    for (auto _ : state) {
        RtcmStreamDecoder dec;
        auto onMessage = [&](const RtcmMessage &m) {
            ++frames;
            if (const auto *h = std::get_if<MsmHeader>(&m.body)) satellites += h->satelliteCount;
        };
        feedInChunks(s, [&](std::string_view chunk) { dec.feed(chunk, onMessage); });
        dec.finish(onMessage);
    }
    benchmark::DoNotOptimize(satellites);
    report(state, s.size(), frames);
}
BENCHMARK(BM_RtcmFrameAndDecode)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

void BM_RtcmFrameDecodeAndJson(benchmark::State &state) {
    const std::string &s = stream50MB();
    std::uint64_t frames = 0, jsonBytes = 0;
    std::string out;
    for (auto _ : state) {
        RtcmStreamDecoder dec;
        auto onMessage = [&](const RtcmMessage &m) {
            ++frames;
            gnss::JsonWriter w(out);
            writeRtcmJson(w, m);
            out.push_back('\n');
            if (out.size() > (1 << 16)) {
                jsonBytes += out.size();
                out.clear();
            }
        };
        feedInChunks(s, [&](std::string_view chunk) { dec.feed(chunk, onMessage); });
        dec.finish(onMessage);
    }
    benchmark::DoNotOptimize(jsonBytes);
    report(state, s.size(), frames);
}
BENCHMARK(BM_RtcmFrameDecodeAndJson)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
