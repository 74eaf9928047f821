// gnss-cli base end to end, against gnss-sim's NV08C-RTK on a pseudo-terminal (and its COM2 on a
// second one), 20 times faster than real time: typed mistakes refused before anything is sent;
// a base set, verified by reading it back, saved, and its RTCM on COM2; the threshold warning; the
// workbench's survey-in saved as a site and used; the receiver's own survey-in. Then the loop: the
// base's COM2 served by gnss-cli serve's caster, a simulated rover fed by gnss-cli ntrip and,
// separately, by Debian's str2str (when installed), each reaching RTK fixed.
#include "cli_run.h"
#include "rtcm/rtcm_framer.h"
#include "serve_process.h"
#include "sim_process.h"
#include "str2str_process.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSocketNotifier>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <fcntl.h>
#include <map>
#include <termios.h>
#include <unistd.h>

using gnss::link::test::SimProcess;
using gnss::test::jsonLines;
using gnss::test::Run;
using gnss::test::ServeProcess;

namespace {

// The simulator's observer (sky_model.h): where the receiver's own fixes are.
constexpr double kLat = 55.7512, kLon = 37.6184, kHeight = 152.0 + 14.6;

QByteArray why(const Run &r) {
    return "exit " + QByteArray::number(r.exitCode) + "\nstdout: " + r.out.right(3000) +
           "\nstderr: " + r.err.right(3000);
}

// gnss-cli with the sites kept in `dataDir`.
Run cli(const QStringList &args, const QString &dataDir = {}, int timeoutMs = 60000) {
    auto env = QProcessEnvironment::systemEnvironment();
    if (!dataDir.isEmpty()) env.insert(QStringLiteral("GNSS_WORKBENCH_DATA_DIR"), dataDir);
    return gnss::test::runProgram(QStringLiteral(GNSS_CLI_PATH), args, {}, timeoutMs, env);
}

// An NV08C-RTK with its COM2 on a second pseudo-terminal.
struct Base {
    SimProcess sim{{"--dialect", "nvs", "--baud", "115200", "--speed", "20", "--com2"}};
    QString com2 = gnss::link::test::firstLine(sim.proc);
    QStringList source() const { return {"--port", sim.device, "--baud", "115200"}; }
};

// What arrives on a pseudo-terminal for `ms`.
QByteArray readPty(const QString &device, int ms) {
    const int fd = ::open(device.toLocal8Bit().constData(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    if (fd < 0) return {};
    termios t{};
    tcgetattr(fd, &t);
    cfmakeraw(&t);
    cfsetispeed(&t, B115200);
    cfsetospeed(&t, B115200);
    tcsetattr(fd, TCSANOW, &t);
    QByteArray got;
    QElapsedTimer timer;
    timer.start();
    char buf[4096];
    while (timer.elapsed() < ms) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n > 0)
            got.append(buf, n);
        else
            QTest::qWait(20);
    }
    ::close(fd);
    return got;
}

std::map<unsigned, int> frameTypes(const QByteArray &bytes, unsigned *station = nullptr) {
    std::map<unsigned, int> types;
    gnss::rtcm::RtcmFramer f;
    f.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())),
           [&](const gnss::rtcm::RtcmFrame &frame) {
               ++types[frame.messageNumber()];
               const auto p = frame.payload();
               if (station && p.size() >= 3) *station = ((p[1] & 0x0F) << 8) | p[2];
           });
    return types;
}

QJsonObject lastWith(const QByteArray &out, const QString &key) {
    QJsonObject found;
    for (const QJsonObject &o : jsonLines(out))
        if (o.contains(key)) found = o[key].toObject();
    return found;
}

QString verdictOf(const QByteArray &out, const QString &key) {
    for (const QJsonObject &o : jsonLines(out))
        if (o["key"].toString() == key) return o["verdict"].toString();
    return {};
}

#define REQUIRE_BASE_SIM(b)                                                                        \
    do {                                                                                           \
        REQUIRE_SIM((b).sim);                                                                      \
        QVERIFY2((b).com2.startsWith("/dev/"), qPrintable("no COM2: " + (b).com2));                \
    } while (0)

} // namespace

class TstBaseCli : public QObject {
    Q_OBJECT
    QTemporaryDir data_;

private slots:
    // Mistakes in what is typed: exit 2 before the port is opened (a port that does not exist
    // would say so otherwise) or, for a receiver that cannot be a base, before anything is sent.
    void mistakesAreRefusedFirst_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        const QStringList none = {"--port", "/dev/null-no-such-port", "--baud", "115200"};
        QTest::newRow("no action") << none << "one action";
        QTest::newRow("no position") << none + QStringList{"set"} << "needs the base's position";
        QTest::newRow("two positions")
                << none + QStringList{"set", "--ecef", "1,2,3", "--llh", "1,2,3"} << "one of";
        QTest::newRow("latitude") << none + QStringList{"set", "--llh", "95,37,150"}
                                  << "latitude: '95' is beyond 90";
        QTest::newRow("DMS minutes")
                << none + QStringList{"set", "--llh", "55 61 0N,37,150"} << "minutes 61";
        QTest::newRow("msl alone")
                << none + QStringList{"set", "--ecef", "1,2,3", "--msl"} << "goes with --llh";
        QTest::newRow("antenna") << none + QStringList{"set", "--llh", "55,37,150",
                                                       "--antenna-height", "-1"}
                                 << "--antenna-height";
        QTest::newRow("unknown site")
                << none + QStringList{"set", "--site", "Nowhere"} << "no site named 'Nowhere'";
        QTest::newRow("no goal") << none + QStringList{"survey"} << "--minutes M or --sigma";
        QTest::newRow("receiver by sigma")
                << none + QStringList{"survey", "--sigma", "1", "--by-receiver"} << "--minutes";
        QTest::newRow("half minutes")
                << none + QStringList{"survey", "--minutes", "1.5", "--by-receiver"}
                << "whole minutes";
        QTest::newRow("rtcm baud alone")
                << none + QStringList{"set", "--llh", "55,37,150", "--rtcm-baud", "9600"}
                << "give --rtcm-port";
        QTest::newRow("not a base")
                << QStringList{"--sim", "geostar", "status"} << "cannot be a base station";
        QTest::newRow("kilometres")
                << QStringList{"--sim", "nvs", "set", "--ecef", "2849.8,2196.1,5249.0"}
                << "not near the Earth's surface";
        QTest::newRow("port 4") << QStringList{"--sim",     "nvs",         "set", "--llh",
                                               "55,37,150", "--rtcm-port", "4"}
                                << "no port 4 can carry RTCM 3";
    }
    void mistakesAreRefusedFirst() {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const Run r = cli(QStringList{"base"} + args, data_.path());
        QVERIFY2(r.exitCode == 2, why(r));
        QVERIFY2(QString::fromUtf8(r.err).contains(says), why(r));
        QVERIFY2(!r.out.contains("\"sentence\""), why(r)); // nothing was sent
    }

    // Set, verified by reading it back, saved; the status says so; COM2 carries the RTCM.
    void aBaseIsSetVerifiedAndSends() {
        Base b;
        REQUIRE_BASE_SIM(b);
        const Run r =
                cli(QStringList{"base"} + b.source() +
                    QStringList{"set", "--llh", "55 45.072N,37 37.104E,165.1", "--antenna-height",
                                "1.5", "--station", "321", "--rtcm-port", "2", "--save"});
        QVERIFY2(r.exitCode == 0, why(r));
        QCOMPARE(verdictOf(r.out, "rtk.MODE"), QStringLiteral("verified"));
        QCOMPARE(verdictOf(r.out, "rtk.BASEXYZ"), QStringLiteral("verified"));
        QCOMPARE(verdictOf(r.out, "rtk.BASEID"), QStringLiteral("verified"));
        QVERIFY(verdictOf(r.out, "port.COM2.protocol").startsWith("confirmed"));
        QVERIFY2(r.out.contains("$PNVGCFG,W"), why(r)); // saved
        const QJsonObject status = lastWith(r.out, "status");
        QCOMPARE(status["role"].toString(), QStringLiteral("base"));
        const QJsonObject p = status["position"].toObject();
        QVERIFY(std::abs(p["lat"].toDouble() - kLat) < 1e-8);
        QVERIFY(std::abs(p["height"].toDouble() - 166.6) < 0.002); // the antenna height added
        QCOMPARE(status["station"].toString(), QStringLiteral("321"));
        QVERIFY(!status["beyond_threshold"].toBool());
        // Read on its own, the same.
        const Run s = cli(QStringList{"base"} + b.source() + QStringList{"status"});
        QVERIFY2(s.exitCode == 0, why(s));
        QCOMPARE(lastWith(s.out, "status")["position"].toObject()["x"], p["x"]);
        // COM2: #1002, #1010 and 1005 of station 321, CRC-valid, nothing else.
        unsigned station = 0;
        const auto types = frameTypes(readPty(b.com2, 1500), &station);
        QVERIFY2(types.count(1002) && types.count(1010) && types.count(1005),
                 qPrintable(QString::number(types.size())));
        QCOMPARE(station, 321u);
    }

    // A position farther than the receiver's threshold: set and verified, with a warning.
    void pastTheThresholdItWarns() {
        Base b;
        REQUIRE_BASE_SIM(b);
        const Run r = cli(QStringList{"base"} + b.source() +
                          QStringList{"set", "--llh", "55.7612,37.6184,166.6"}); // 1.1 km north
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonObject status = lastWith(r.out, "status");
        QVERIFY2(status["beyond_threshold"].toBool(), why(r));
        QVERIFY(status["distance_m"].toDouble() > 1000);
        QVERIFY2(r.err.contains("it sends no corrections"), why(r));
    }

    // The workbench's survey-in, saved as a site; the site then set as the base.
    void aSurveyBecomesASiteAndTheBase() {
        Base b;
        REQUIRE_BASE_SIM(b);
        const Run r = cli(QStringList{"base"} + b.source() +
                                  QStringList{"survey", "--minutes", "1", "--save-site",
                                              "Roof mark", "--set", "--rtcm-port", "2"},
                          data_.path());
        QVERIFY2(r.exitCode == 0, why(r));
        int progress = 0;
        for (const QJsonObject &o : jsonLines(r.out)) progress += o.contains("survey") ? 1 : 0;
        QVERIFY2(progress >= 30, why(r)); // a line a simulated second
        const QJsonObject result = lastWith(r.out, "result");
        QVERIFY(result["positions"].toInt() >= 250); // 5 Hz
        QVERIFY(std::abs((result["lat"].toDouble() - kLat) * 111320) < 1.0);
        QVERIFY(std::abs(result["height"].toDouble() - kHeight) < 2.0);
        QVERIFY(result["sigma_up"].toDouble() > result["accuracy"].toDouble());
        QCOMPARE(verdictOf(r.out, "rtk.BASEXYZ"), QStringLiteral("verified"));
        // The site list has it, and setting it again is nothing to do.
        const Run list = cli({"sites", "list", "--json"}, data_.path());
        QVERIFY2(list.out.contains("Roof mark") && list.out.contains("survey-in"), why(list));
        const Run again =
                cli(QStringList{"base"} + b.source() + QStringList{"set", "--site", "roof"},
                    data_.path());
        QVERIFY2(again.exitCode == 0, why(again));
        QVERIFY2(again.out.contains("\"nothing_to_do\":true"), why(again));
    }

    // The receiver's own averaging: its time followed, the position it found read back.
    void theReceiverSurveysItself() {
        Base b;
        REQUIRE_BASE_SIM(b);
        const Run r = cli(QStringList{"base"} + b.source() +
                          QStringList{"survey", "--minutes", "1", "--by-receiver"});
        QVERIFY2(r.exitCode == 0, why(r));
        QCOMPARE(verdictOf(r.out, "rtk.MODE"), QStringLiteral("verified"));
        const QJsonObject result = lastWith(r.out, "result");
        QCOMPARE(result["by"].toString(), QStringLiteral("receiver"));
        QVERIFY2(std::abs((result["lat"].toDouble() - kLat) * 111320) < 2.0, why(r));
        QCOMPARE(lastWith(r.out, "status")["role"].toString(), QStringLiteral("base_averaging"));
    }

    // The loop: base COM2 → gnss-cli serve → gnss-cli ntrip → simulated rover → RTK fixed; and
    // the same rover fed by str2str instead.
    void aRoverReachesRtkFixedFromTheServedBase_data() {
        QTest::addColumn<bool>("str2str");
        QTest::newRow("gnss-cli ntrip") << false;
        QTest::newRow("str2str") << true;
    }
    void aRoverReachesRtkFixedFromTheServedBase() {
        QFETCH(bool, str2str);
        const QString rtklib = QStandardPaths::findExecutable(QStringLiteral("str2str"));
        if (str2str && rtklib.isEmpty()) QSKIP("str2str (Debian package rtklib) is not installed");
        Base b;
        REQUIRE_BASE_SIM(b);
        const Run set = cli(QStringList{"base"} + b.source() +
                            QStringList{"set", "--llh", "55.7512,37.6184,166.6", "--rtcm-port", "2",
                                        "--station", "42"});
        QVERIFY2(set.exitCode == 0, why(set));
        ServeProcess serve({"--port", b.com2, "--baud", "115200", "--ntrip", "127.0.0.1:0/NVSB",
                            "--duration", "60"});
        const quint16 port = serve.ntripPort();
        QVERIFY2(port != 0, serve.err.constData());
        SimProcess rover({"--dialect", "nvs", "--baud", "115200", "--speed", "20", "--seed", "2"});
        REQUIRE_SIM(rover);
        const QString mount = QStringLiteral("127.0.0.1:%1").arg(port);
        if (!str2str) {
            const Run r = cli({"ntrip", "--caster", mount, "--mount", "NVSB", "--port",
                               rover.device, "--baud", "115200", "--duration", "6"},
                              {}, 30000);
            QVERIFY2(r.out.contains("\"rtk_fixed\""), why(r));
            return;
        }
        // str2str writes to the rover's line; its epochs are read with gnss-cli monitor.
        QProcess rtk;
        rtk.setProcessChannelMode(QProcess::MergedChannels);
        rtk.start(rtklib, {"-in", "ntrip://@" + mount + "/NVSB", "-out",
                           "serial://" + rover.device.mid(5) + ":115200"});
        QVERIFY(rtk.waitForStarted(5000));
        const Run m = cli({"monitor", "--port", rover.device, "--baud", "115200", "--duration", "6",
                           "--epochs"},
                          {}, 30000);
        gnss::test::stopStr2str(rtk);
        QVERIFY2(m.out.contains("\"rtk_fixed\""), why(m) + "\nstr2str: " + rtk.readAll());
    }
};

QTEST_GUILESS_MAIN(TstBaseCli)
#include "tst_base_cli.moc"
