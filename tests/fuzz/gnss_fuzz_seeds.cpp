// gnss_fuzz_seeds OUT_DIR: writes the seeds that the project's encoders make, for
// tests/fuzz/make_corpus.sh (which adds simulator output and the sentences typed in the tests):
//
//   OUT_DIR/fuzz_rtcm/               RTCM 3 frames from protocol/rtcm's encoder: 1005/1006,
//                                    1007/1008/1033, MSM1-7 of every system, ephemerides, 1230,
//                                    and a stream mixing them with NMEA text and noise
//   OUT_DIR/fuzz_settings_roundtrip/ every setting of every schema with its default value (or
//                                    its first option), in fuzz_settings_input.h's format
//   OUT_DIR/fuzz_profile_import/     a profile per dialect (schema defaults, write-only list),
//                                    as profileToJson writes it
#include "config/setting_values.h"
#include "config/settings_profile.h"
#include "fuzz_settings_input.h"
#include "rtcm/rtcm_encoder.h"

#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace gnss;
using namespace gnss::rtcm;
namespace fs = std::filesystem;

namespace {

fs::path g_out;
int g_written = 0;

// Seeds are named seed_* (make_corpus.sh replaces those and keeps the rest).
void write(const std::string &harness, const std::string &name, std::string_view bytes) {
    const fs::path dir = g_out / harness;
    fs::create_directories(dir);
    std::ofstream(dir / ("seed_" + name), std::ios::binary)
            .write(bytes.data(), std::streamsize(bytes.size()));
    ++g_written;
}

// fuzz_rtcm's first byte picks the chunking: 0x23 cuts into chunks of 1 to 8 bytes.
void writeRtcm(const std::string &name, const std::string &frames) {
    write("fuzz_rtcm", name, "\x23" + frames);
}

std::uint64_t satMask(std::initializer_list<unsigned> ids) {
    std::uint64_t m = 0;
    for (const unsigned id : ids) m |= std::uint64_t(1) << (64 - id);
    return m;
}
std::uint32_t sigMask(std::initializer_list<unsigned> ids) {
    std::uint32_t m = 0;
    for (const unsigned id : ids) m |= std::uint32_t(1) << (32 - id);
    return m;
}

MsmHeader msm(System s, unsigned type) {
    MsmHeader h;
    h.system = s;
    h.msmType = type;
    h.station = 2003;
    h.satelliteMask = satMask({2, 5, 13, 24});
    h.signalMask = sigMask({2, 9, 16});
    if (s == System::Glonass) h.gloDayOfWeek = 5;
    const unsigned cells = unsigned(std::popcount(h.satelliteMask) * std::popcount(h.signalMask));
    for (unsigned i = 0; i < cells; ++i)
        if (i % 3 != 1) h.cellMask |= std::uint64_t(1) << i;
    h.epochMs = 345600000u + type;
    h.multipleMessage = type % 2 == 0;
    h.iods = type;
    h.smoothing = type > 4;
    return h;
}

void rtcmSeeds() {
    StationArp arp;
    arp.station = 2003;
    arp.gps = arp.glonass = arp.galileo = true;
    arp.x = 1114104.5999;
    arp.y = -4850729.7108;
    arp.z = 3975521.4643;
    const std::string s1005 = encodeStationArp(arp);
    writeRtcm("1005", s1005);
    arp.antennaHeight = 1.234;
    writeRtcm("1006", encodeStationArp(arp));

    AntennaInfo ant;
    ant.station = 2003;
    ant.antennaDescriptor = "TRM59800.00     SCIS";
    ant.setupId = 1;
    writeRtcm("1007", encodeAntennaInfo(1007, ant));
    ant.antennaSerial = "5000118342";
    writeRtcm("1008", encodeAntennaInfo(1008, ant));
    ant.receiverType = "NV08C-RTK";
    ant.firmware = "0410";
    ant.receiverSerial = "A1B2C3";
    const std::string s1033 = encodeAntennaInfo(1033, ant);
    writeRtcm("1033", s1033);

    const System systems[] = {System::Gps,  System::Glonass, System::Galileo, System::Sbas,
                              System::Qzss, System::BeiDou,  System::NavIC};
    const char *names[] = {"gps", "glonass", "galileo", "sbas", "qzss", "beidou", "navic"};
    std::string epoch; // one epoch of MSM7 from every system
    for (std::size_t k = 0; k < std::size(systems); ++k) {
        std::string all;
        for (unsigned type = 1; type <= 7; ++type) all += encodeMsm(msm(systems[k], type));
        writeRtcm(std::string("msm1-7_") + names[k], all);
        epoch += encodeMsm(msm(systems[k], 7));
    }

    std::string ephemerides;
    for (unsigned number : {1019u, 1020u, 1042u, 1044u, 1045u, 1046u}) {
        Ephemeris e;
        e.satellite = 7;
        e.week = 250;
        e.iode = 42;
        e.iodc = 42;
        e.tocSeconds = 7200;
        e.toeSeconds = 7200;
        e.health = 0;
        if (number == 1020) {
            e.frequencyChannel = -3;
            e.tkSeconds = 3600;
            e.tbMinutes = 60;
        }
        const std::string f = encodeEphemeris(number, e);
        writeRtcm(std::to_string(number), f);
        ephemerides += f;
    }

    GlonassBiases b;
    b.station = 2003;
    b.aligned = true;
    b.present = {true, false, true, false};
    b.biases = {1.02, std::nullopt, -0.5, std::nullopt};
    const std::string s1230 = encodeGlonassBiases(b);
    writeRtcm("1230", s1230);

    // A base station's stream: NMEA text and noise between frames, a frame with a bad CRC, and
    // one cut short at the end.
    std::string bad = s1005;
    bad[6] ^= 0x10;
    writeRtcm("mixed_stream", "$GPGGA,,,,,,0,00,,,M,,M,,*66\r\n" + s1005 + "\xD3\xD3\x00" + epoch +
                                      s1230 + "noise" + bad + s1033 + ephemerides +
                                      s1005.substr(0, 10));
}

void settingsSeeds() {
    const auto &dialects = fuzz::dialectsWithSettings();
    for (std::size_t d = 0; d < dialects.size(); ++d) {
        const auto schema = dialects[d]->settings;
        for (std::size_t i = 0; i < schema.size(); ++i) {
            const SettingDef &def = schema[i];
            std::string value(def.defaultValue);
            if (value.empty() && !def.options.empty()) value = def.options.front().value;
            if (value.empty()) continue;
            const std::string bytes = std::string(1, char(d)) + fuzz::settingsRecord(i, value);
            write("fuzz_settings_roundtrip",
                  std::string(dialects[d]->id) + "_" + std::string(def.key), bytes);
        }
    }
}

void profileSeeds() {
    const DialectRegistry reg = makeBuiltinRegistry();
    const auto dialects = reg.dialects();
    for (std::size_t d = 0; d < dialects.size(); ++d) {
        config::Profile p;
        p.dialect = dialects[d]->id;
        p.model = "model";
        p.firmware = "1.0";
        p.created = "2024-03-15T10:00:00Z";
        for (const SettingDef &def : dialects[d]->settings) {
            if (!config::isWritable(def) || def.defaultValue.empty()) continue;
            p.values.push_back({std::string(def.key), std::string(def.defaultValue)});
            if (def.access == SettingAccess::WriteOnly) p.writeOnly.emplace_back(def.key);
        }
        // Byte 0 picks the dialect the profile is read with: 1 + d is its own, 0 none.
        const QByteArray json = config::profileToJson(p);
        write("fuzz_profile_import", std::string(dialects[d]->id),
              std::string(1, char(1 + d)) + json.toStdString());
    }
    write("fuzz_profile_import", "empty_values",
          std::string(1, '\0') + R"({"format":"gnss-workbench-settings","version":1,)"
                                 R"("dialect":"nmea","values":{},"write_only":[]})");
}

} // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: gnss_fuzz_seeds OUT_DIR\n");
        return 2;
    }
    g_out = argv[1];
    rtcmSeeds();
    settingsSeeds();
    profileSeeds();
    std::printf("%d seeds written under %s\n", g_written, argv[1]);
    return 0;
}
