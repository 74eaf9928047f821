// gnss-cli rtcm end to end: the built executable on a file made by the encoder and on standard
// input; JSON lines on stdout, the summary on stderr, exit codes.
#include "cli_run.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm_test_support.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace gnss::rtcm;
using namespace rtcm_test;
using namespace gnss::test;

namespace {

// A base station's minute: 1005, 1033, 1230, then GPS and GLONASS MSM7 and a GPS ephemeris, with
// NMEA and a corrupted frame between.
QByteArray baseStationStream() {
    StationArp arp;
    arp.station = 2003;
    arp.gps = arp.glonass = true;
    arp.x = 2849878.1521;
    arp.y = 2195934.8381;
    arp.z = 5249094.9248;
    AntennaInfo info;
    info.station = 2003;
    info.antennaDescriptor = "ADVNULLANTENNA";
    info.receiverType = "GNSS WORKBENCH SIM";
    info.firmware = "0.1.0";
    GlonassBiases biases;
    biases.station = 2003;
    biases.present = {true, false, true, false};
    biases.biases = {1.5, std::nullopt, -2.0, std::nullopt};
    MsmHeader gps;
    gps.system = System::Gps;
    gps.msmType = 7;
    gps.station = 2003;
    gps.satelliteMask = 0xF000000000000000; // 1-4
    gps.signalMask = 0x40000000;            // 2 (1C)
    gps.cellMask = 0xF;
    MsmHeader glo = gps;
    glo.system = System::Glonass;
    glo.gloDayOfWeek = 1;
    Ephemeris eph;
    eph.satellite = 4;
    eph.week = 300;
    eph.iode = 12;

    std::string s = "$GPGGA,000000.00,,,,,0,,,,,,,,*66\r\n";
    s += encodeStationArp(arp) + encodeAntennaInfo(1033, info) + encodeGlonassBiases(biases);
    std::string bad = encodeMsm(gps);
    bad[20] ^= 0x5A;
    s += bad;
    for (std::uint32_t ms = 0; ms < 3000; ms += 1000) {
        gps.epochMs = ms;
        glo.epochMs = ms;
        s += encodeMsm(gps) + encodeMsm(glo);
    }
    s += encodeEphemeris(1019, eph);
    return QByteArray::fromStdString(s);
}

} // namespace

class TstRtcmCli : public QObject {
    Q_OBJECT
private slots:
    void rtcmPrintsOneJsonObjectPerMessage() {
        QTemporaryDir dir;
        const QString path = dir.filePath("base.rtcm3");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(baseStationStream());
        f.close();

        const Run r = runCli({"rtcm", path});
        QCOMPARE(r.status, QProcess::NormalExit);
        QCOMPARE(r.exitCode, 0);
        const auto lines = jsonLines(r.out);
        QCOMPARE(lines.size(), 10);
        QCOMPARE(lines[0]["type"].toInt(), 1005);
        QCOMPARE(lines[0]["station"].toInt(), 2003);
        QCOMPARE(lines[0]["x"].toDouble(), 2849878.1521);
        QVERIFY(std::fabs(lines[0]["lat"].toDouble() - 55.75222) < 1e-5);
        QCOMPARE(lines[1]["type"].toInt(), 1033);
        QCOMPARE(lines[1]["receiver_type"].toString(), QString("GNSS WORKBENCH SIM"));
        QCOMPARE(lines[2]["type"].toInt(), 1230);
        QCOMPARE(lines[2]["biases"].toObject()["2C"].toDouble(), -2.0);
        QCOMPARE(lines[3]["type"].toInt(), 1077);
        QCOMPARE(lines[3]["satellites"].toArray(), (QJsonArray{1, 2, 3, 4}));
        QCOMPARE(lines[4]["type"].toInt(), 1087);
        QCOMPARE(lines[4]["day_of_week"].toInt(), 1);
        QCOMPARE(lines[7]["tow_ms"].toInt(), 2000);
        QCOMPARE(lines[9]["type"].toInt(), 1019);
        QCOMPARE(lines[9]["iode"].toInt(), 12);
        for (const auto &o : lines) QVERIFY(!o.contains("error"));

        const QJsonObject summary = QJsonDocument::fromJson(r.err.trimmed()).object();
        QCOMPARE(summary["frames"].toInt(), 10);
        // The corrupted frame, then the 0xD3 inside it read as a header: station 2003 (0x7D3)
        // after message number 0x435 puts the bytes 43 57 D3 00 in every MSM of this station.
        QCOMPARE(summary["crc_failures"].toInt(), 2);
        QVERIFY(summary["bytes_skipped"].toInt() >= 35); // the NMEA line and the bad frame
        QCOMPARE(summary["bytes"].toInt(), int(QFileInfo(path).size()));
        QCOMPARE(summary["types"].toObject(), (QJsonObject{{"1005", 1},
                                                           {"1019", 1},
                                                           {"1033", 1},
                                                           {"1077", 3},
                                                           {"1087", 3},
                                                           {"1230", 1}}));
    }

    void rtcmReadsStandardInputAndSurvivesNoise() {
        QByteArray noise(20000, '\0');
        quint32 x = 12345;
        for (auto &c : noise) {
            x = x * 1103515245u + 12345u;
            c = char(x >> 24);
        }
        const Run r = runCli({"rtcm", "-"}, noise + baseStationStream() + noise.left(100));
        QCOMPARE(r.status, QProcess::NormalExit);
        QCOMPARE(r.exitCode, 0);
        const QJsonObject summary = QJsonDocument::fromJson(r.err.trimmed()).object();
        QVERIFY(summary["frames"].toInt() >= 10);
        QCOMPARE(summary["bytes_in_frames"].toInt() + summary["bytes_skipped"].toInt(),
                 summary["bytes"].toInt());
        QCOMPARE(jsonLines(r.out).size(), summary["frames"].toInt());
    }

    void rtcmExitCodesSayWhatWentWrong() {
        Run r = runCli({"rtcm", "/nonexistent/base.rtcm3"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("/nonexistent/base.rtcm3"));
        r = runCli({"rtcm", "a", "b"});
        QCOMPARE(r.exitCode, 2);
        r = runCli({"rtcm", "--lenient", "-"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(runCli({"--help"}).out.contains("rtcm [FILE|-]"));
    }
};

QTEST_GUILESS_MAIN(TstRtcmCli)
#include "tst_rtcm_cli.moc"
