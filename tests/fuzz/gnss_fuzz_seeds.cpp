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
//   OUT_DIR/fuzz_ntrip_response/     caster replies in the NTRIP 1 and 2 forms of tests/ntrip
//                                    and tests/support/test_caster.h (ICY, SOURCETABLE,
//                                    HTTP with chunked gnss/data and tables, 401, 404, 503,
//                                    ERROR lines, not a caster), RTCM from the encoder, chunked
//                                    bodies, source tables
//   OUT_DIR/fuzz_recording_index/    recordings written by link::Recorder (chunks, a command, a
//                                    lost and restored link, an appended session), and what
//                                    becomes of one: a torn last index line, a cut data file, a
//                                    hole, CR LF, another program's file as index, no index
#include "config/setting_values.h"
#include "config/settings_profile.h"
#include "core/sentence_builder.h"
#include "fuzz_settings_input.h"
#include "link/recorder.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm_test_support.h"
#include "source_table_examples.h"

#include <QFile>
#include <QTemporaryDir>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace gnss;
using namespace gnss::rtcm;
using rtcm_test::satMask;
using rtcm_test::sigMask;
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

// fuzz_mixed_stream: NMEA sentences and RTCM frames interleaved on one line, as a base that
// talks NMEA and sends its corrections on the same port; byte 0 picks the chunking.
void mixedSeeds(const std::string &station, const std::string &observations) {
    const std::string gga =
            "$GPGGA,100000.00,5545.0720,N,03737.1042,E,1,08,1.00,151.2,M,14.6,M,,*53\r\n";
    const std::string rmc = "$GPRMC,100000.00,A,5545.0720,N,03737.1042,E,0.0,0.0,150324,,,A*5D\r\n";
    std::string clean, noisy, cut;
    for (int i = 0; i < 4; ++i) {
        clean += gga + observations + rmc + (i == 0 ? station : std::string());
        noisy += gga + "\x01\xff junk" + observations + "$GPR" + station + rmc;
    }
    cut = clean.substr(0, clean.size() / 2) + gga + clean.substr(clean.size() / 2 + 7);
    write("fuzz_mixed_stream", "clean", std::string(1, '\0') + clean);
    write("fuzz_mixed_stream", "noisy", "\x23" + noisy);
    write("fuzz_mixed_stream", "cut", "\x11" + cut);
}

MsmHeader msm(System s, unsigned type) {
    MsmHeader h = rtcm_test::msmHeader(s, type, satMask({2, 5, 13, 24}), sigMask({2, 9, 16}));
    h.station = 2003;
    if (s == System::Glonass) h.gloDayOfWeek = 5;
    h.epochMs = 345600000u + type;
    return h;
}

void rtcmSeeds() {
    StationArp arp{.station = 2003,
                   .gps = true,
                   .glonass = true,
                   .galileo = true,
                   .x = 1114104.5999,
                   .y = -4850729.7108,
                   .z = 3975521.4643};
    const std::string s1005 = encodeStationArp(arp);
    writeRtcm("1005", s1005);
    mixedSeeds(s1005, encodeMsm(msm(System::Gps, 7)));
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
        Ephemeris e = rtcm_test::ephemeris(7, 250, 42, 42, 7200, 7200, 0);
        if (number == 1020) e.frequencyChannel = -3, e.tkSeconds = 3600, e.tbMinutes = 60;
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

// Legacy observables 1001-1004 and 1009-1012: two satellites each, one without L2 pseudorange
// and L1 phase (sent as invalid); all eight in one stream too.
void legacyRtcmSeeds() {
    std::string all;
    for (const unsigned number : {1001u, 1002u, 1003u, 1004u, 1009u, 1010u, 1011u, 1012u}) {
        LegacyObservables o{.number = number, .station = 2003, .epochMs = 345600000};
        o.synchronous = number != 1004 && number != 1012;
        for (unsigned i = 0; i < 2; ++i) {
            LegacySatellite s{.id = 5 + i, .l1 = {.pseudorange = 21e6 + 1234.56 * i}};
            if (number >= 1009) s.frequencyChannel = int(i) - 2;
            if (i == 0) s.l1.phaseRange = 21e6 + 0.5, s.l1.cnr = 44.25;
            s.l2 = LegacySignal{.code = i, .phaseRange = 21e6 + 1234.56 * i - 3.5, .cnr = 40};
            if (i == 0) s.l2->pseudorange = 21e6 + 4.2;
            o.satellites.push_back(s);
        }
        const std::string f = encodeLegacy(o);
        writeRtcm(std::to_string(number), f);
        all += f;
    }
    writeRtcm("legacy_stream", all);
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

// ---- NTRIP replies: byte 0 the mode (0 a whole reply, 1 a chunked body, 2 a source table;
// + 4: repeated past the longest head), byte 1 the chunking it arrives in, byte 2 the rest
// (fuzz_ntrip_response.cpp).

void writeNtrip(const std::string &name, std::uint8_t mode, std::uint8_t chunking,
                std::string_view payload) {
    std::string bytes{char(mode), char(chunking), char(0x5A)};
    bytes.append(payload);
    write("fuzz_ntrip_response", name, bytes);
}

// As an NTRIP 2 caster sends a stream: HTTP chunks of the given sizes, cycled.
std::string httpChunks(std::string_view data, std::initializer_list<std::size_t> sizes,
                       std::string_view extension = {}) {
    std::string out;
    auto size = sizes.begin();
    for (std::size_t pos = 0; pos < data.size();) {
        const std::size_t n = std::min(*size, data.size() - pos);
        if (++size == sizes.end()) size = sizes.begin();
        char head[32];
        std::snprintf(head, sizeof head, "%zx", n);
        out += head;
        out += extension;
        out += "\r\n";
        out.append(data.substr(pos, n));
        out += "\r\n";
        pos += n;
    }
    return out + "0\r\n\r\n";
}

void ntripSeeds() {
    std::string rtcm = encodeStationArp({.station = 7,
                                         .gps = true,
                                         .glonass = true,
                                         .x = 2845455.0,
                                         .y = 2160465.0,
                                         .z = 5265313.0});
    rtcm += encodeMsm(msm(System::Gps, 4));
    rtcm += encodeMsm(msm(System::Glonass, 4));

    // The tables of tests/support/source_table_examples.h and tests/support/test_caster.h.
    const std::string table = ntrip_test::kSourceTable;
    const std::string casterTable =
            "STR;MOUNT;Test base;RTCM 3.2;1005(1),1074(1),1084(1);1;GPS+GLO;TEST;RUS;55.75;37.62;1;"
            "0;gnss-sim;none;B;N;9600;\r\n"
            "STR;FAR;Far base;RTCM 3.3;1005(10);2;GPS;TEST;RUS;59.93;30.34;0;0;x;none;B;N;9600;\r\n"
            "STR;OLD;Old base;RTCM 2.3;1;2;GPS;TEST;RUS;55.76;37.63;0;0;x;none;B;N;2400;\r\n"
            "CAS;127.0.0.1;2101;Test;Tests;0;RUS;55.75;37.62;;0;\r\n"
            "NET;TEST;Tests;B;N;none;none;none;\r\n"
            "ENDSOURCETABLE\r\n";
    const std::string rtklib = ntrip_test::kRtklibSourceTable;
    const std::string v2 = "HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\n";

    writeNtrip("icy_rtcm", 0, 0x23, "ICY 200 OK\r\n" + rtcm);
    writeNtrip("icy_headers_rtcm", 0, 0x11,
               "ICY 200 OK\r\nServer: Caster/1.0\r\nDate: today\r\n\r\n" + rtcm);
    writeNtrip("icy_nmea_text", 0, 0x00, "ICY 200 OK\r\n$GPGGA,1,2*00\r\nhello world\r\n");
    writeNtrip("v2_chunked_rtcm", 0, 0x2B,
               v2 + "Content-Type: gnss/data\r\nTransfer-Encoding: chunked\r\n\r\n" +
                       httpChunks(rtcm, {7, 13, 1, 64}));
    writeNtrip("v2_chunked_extensions", 0, 0x1C,
               v2 + "Content-Type: gnss/data\r\nTransfer-Encoding: gzip, chunked\r\n\r\n" +
                       httpChunks(rtcm, {25}, ";x=1"));
    writeNtrip("v2_data_any_case", 0, 0x09,
               "HTTP/1.1 200 OK\r\nntrip-version: Ntrip/2.0\r\ncontent-type: GNSS/Data; x=1\r\n"
               "Content-Length: " +
                       std::to_string(rtcm.size()) + "\r\n\r\n" + rtcm);
    writeNtrip("http10_no_type", 0, 0x05, "HTTP/1.0 200 OK\r\n\r\n" + rtcm);
    writeNtrip("v1_sourcetable", 0, 0x23,
               "SOURCETABLE 200 OK\r\nServer: RTKLIB 2.4.3 b34\r\nContent-Type: text/plain\r\n"
               "Content-Length: " +
                       std::to_string(rtklib.size()) + "\r\n\r\n" + rtklib);
    writeNtrip("v2_sourcetable", 0, 0x14,
               v2 + "Content-Type: gnss/sourcetable\r\n\r\n" + casterTable);
    writeNtrip("v2_sourcetable_chunked", 0, 0x32,
               v2 + "Content-Type: gnss/sourcetable\r\nTransfer-Encoding: chunked\r\n\r\n" +
                       httpChunks(table, {100, 3}));
    writeNtrip("v2_table_text_plain", 0, 0x06,
               "HTTP/1.1 200 OK\r\nContent-Type: text/plain\r\n\r\n" + rtklib);
    writeNtrip("401_rtklib", 0, 0x00, "HTTP/1.0 401 Unauthorized\r\n");
    writeNtrip("401_v2_page", 0, 0x13,
               "HTTP/1.1 401 Unauthorized\r\nNtrip-Version: Ntrip/2.0\r\n"
               "WWW-Authenticate: Basic realm=\"/MOUNT\"\r\n\r\n<html/>");
    writeNtrip("404", 0, 0x02, "HTTP/1.1 404 Not Found\r\n\r\n");
    writeNtrip("503", 0, 0x02, "HTTP/1.1 503 Service Unavailable\r\nRetry-After: 5\r\n\r\n");
    writeNtrip("error_line", 0, 0x01, "ERROR - Bad Password\r\n");
    writeNtrip("web_page", 0, 0x07,
               "HTTP/1.1 200 OK\r\nContent-Type: text/html\r\n\r\n<html><body>hi</body></html>");
    writeNtrip("ssh_banner", 0, 0x03, "SSH-2.0-OpenSSH_9.2\r\n");
    writeNtrip("rtcm_no_head", 0, 0x03, rtcm);
    writeNtrip("long_head", 4, 0x37, "HTTP/1.1 200 OK\r\nX-Filler: aaaaaaaaaaaaaaaaaaaaaaaa\r\n");

    writeNtrip("chunked_body_rtcm", 1, 0x23, httpChunks(rtcm, {7, 13, 1, 64}));
    writeNtrip("chunked_body_trailers", 1, 0x00,
               "3;name=value;x\r\nabc\r\n000A\r\n0123456789\r\n0\r\nX-Checksum: 1\r\n\r\nafter");
    writeNtrip("chunked_body_bare_lf", 1, 0x11, "3\nabc\n0\n\n");
    writeNtrip("chunked_body_broken", 1, 0x02, "3\r\nabcd\r\n0\r\n\r\n");

    writeNtrip("table", 2, 0x2F, table);
    writeNtrip("table_caster", 2, 0x13, casterTable);
    writeNtrip("table_garbage", 2, 0x05,
               "<html>\r\nhello\r\nSTR;M;x\r\n\xff\xfe\r\n\r\n  \r\nSTR;;x;RTCM 3\r\n"
               "STR;M;x;RTCM 3;;two;GPS;N;RUS;north;east;x;y;g;none;B;N;fast;\r\nSTR;A;x\nENDSOURCE"
               "TABLE\n");
}

// ---- Recordings: byte 0 which files exist (0 both, 1 the data only, 2 the index only; + 4: the
// log viewer opens it), bytes 1-2 the index's length, the index, the data
// (fuzz_recording_index.cpp).

void writeRecording(const std::string &name, std::uint8_t control, const std::string &index,
                    const std::string &data) {
    std::string bytes{char(control), char(index.size() & 0xFF), char((index.size() >> 8) & 0xFF)};
    bytes += index;
    bytes += data;
    write("fuzz_recording_index", name, bytes);
}

std::string readFile(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll().toStdString() : std::string();
}

// Five seconds of a receiver at 1 Hz, with valid checksums.
std::string receiverOutput(int fromSecond, int seconds) {
    std::string out;
    for (int t = fromSecond; t < fromSecond + seconds; ++t) {
        char time[16];
        std::snprintf(time, sizeof time, "1000%02d.00", t);
        const std::string ts(time);
        out += buildSentence("GPGGA," + ts +
                             ",5540.0000,N,03730.0000,E,1,08,0.9,150.0,M,14.0,M,,") +
               "\r\n";
        out += buildSentence("GPGSA,A,3,02,05,13,24,,,,,,,,,1.8,0.9,1.5") + "\r\n";
        out += buildSentence("GPRMC," + ts + ",A,5540.0000,N,03730.0000,E,0.0,0.0,150324,,,A") +
               "\r\n";
    }
    return out;
}

void recordingSeeds() {
    QTemporaryDir dir;
    const QString path = dir.filePath("run.nmea");
    qint64 now = 1710496800000; // 2024-03-15T10:00:00Z
    const std::string first = receiverOutput(0, 3), second = receiverOutput(5, 2);
    {
        link::Recorder rec(nullptr, [&] { return now; });
        rec.open(path, QStringLiteral("/dev/ttyUSB0 at 115200 baud"));
        // Chunks as a serial port delivers them: anywhere, mid-sentence and between CR and LF.
        for (std::size_t pos = 0, k = 0; pos < first.size(); ++k) {
            const std::size_t n = std::min<std::size_t>(first.size() - pos, 17 + (k * 37) % 120);
            rec.received(QByteArray::fromStdString(first.substr(pos, n)));
            pos += n;
            now += 100;
        }
        rec.sent("$PNVGVER*4E\r\n");
        now += 1000;
        rec.gap(QStringLiteral("link lost: /dev/ttyUSB0: No such device"));
        now += 2000;
        rec.gap(QStringLiteral("link back: /dev/ttyUSB0 at 115200 baud"));
        rec.received(QByteArray::fromStdString(second.substr(0, 200)));
    }
    {
        now += 500;
        link::Recorder rec(nullptr, [&] { return now; });
        rec.open(path, QStringLiteral("/dev/ttyUSB0"), true); // recording again, appended
        rec.received(QByteArray::fromStdString(second.substr(200)));
    }
    const std::string index = readFile(path + ".idx"), data = readFile(path);

    writeRecording("recorder", 0, index, data);
    writeRecording("recorder_viewer", 4, index, data);
    // The recorder died mid-line, or before the index line of its last chunk.
    const std::size_t lastLine = index.rfind('\n', index.size() - 2) + 1;
    writeRecording("torn_last_line", 4, index.substr(0, lastLine + 9), data);
    writeRecording("last_chunk_unindexed", 0, index.substr(0, lastLine), data);
    // The data file cut short: the index goes past its end.
    writeRecording("data_cut", 4, index, data.substr(0, data.size() / 2));
    // A hole: an R line gone.
    const std::size_t r3 = index.find("\nR ", index.find("\nR ", index.find("\nR ") + 1) + 1);
    std::string holed = index;
    holed.erase(r3 + 1, index.find('\n', r3 + 1) - r3);
    writeRecording("hole", 0, holed, data);
    // An index copied through Windows (CR LF).
    std::string crlf;
    for (char c : index) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    writeRecording("crlf", 4, crlf, data);
    // Another program's file beside the log, or the log itself.
    writeRecording("foreign_csv", 4, "time,lat,lon\n10:00:00,55.6667,37.5\n", data);
    writeRecording("foreign_json", 0,
                   R"({"format":"gnss-workbench-settings","version":1})"
                   "\n",
                   data);
    writeRecording("foreign_nmea", 0, data.substr(0, 600), data);
    writeRecording("comments_only", 4, "# gnss-workbench recording index 1 (docs/recording.md)\n",
                   data);
    writeRecording("empty_index", 0, "", data);
    writeRecording("no_index", 5, "", data);
    writeRecording("no_data", 2, index, "");
}

} // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: gnss_fuzz_seeds OUT_DIR\n");
        return 2;
    }
    g_out = argv[1];
    rtcmSeeds();
    legacyRtcmSeeds();
    settingsSeeds();
    profileSeeds();
    ntripSeeds();
    recordingSeeds();
    std::printf("%d seeds written under %s\n", g_written, argv[1]);
    return 0;
}
