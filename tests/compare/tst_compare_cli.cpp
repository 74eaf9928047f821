// gnss-cli compare end to end: logs gnss-sim wrote (--duration: the same ones every time) of one
// sky, the second told to differ (--offset, --cn0-offset, --drop); and the same receivers live
// on pseudo-terminals at different speeds, found by baud detection. The report gives back what
// the simulator was told, and the live numbers agree with the logs'.
#include "cli_run.h"
#include "compare_json.h"
#include "sim_process.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using gnss::link::test::SimProcess;
using gnss::test::Run;

namespace {

const QStringList kTold = {"--offset",         "0.3,-0.2,0.5", "--cn0-offset",
                           "GPS:-3,GLONASS:2", "--drop",       "G05,R12"};

Run cli(const QStringList &args) {
    return gnss::test::runCli(args, {}, 120000);
}

QByteArray why(const Run &r) {
    return "exit " + QByteArray::number(r.exitCode) + "\nstdout: " + r.out.right(3000) +
           "\nstderr: " + r.err;
}

double mean(const QJsonObject &receiver, const char *axis) {
    return gnss::test::compareMean(receiver, axis);
}

double cn0(const QJsonObject &receiver, const char *system) {
    return gnss::test::compareCn0(receiver, system);
}

// The report's second receiver shows what the simulator was told (NMEA's digits: the standard
// receiver prints 4 decimals of a minute, about 10 cm east here, so the mean is compared).
void checkTold(const QJsonObject &told, int matched, double tolerance) {
    QVERIFY2(std::abs(mean(told, "east") - 0.3) < tolerance,
             qPrintable(QString::number(mean(told, "east"))));
    QVERIFY2(std::abs(mean(told, "north") + 0.2) < tolerance,
             qPrintable(QString::number(mean(told, "north"))));
    QVERIFY2(std::abs(mean(told, "up") - 0.5) < tolerance,
             qPrintable(QString::number(mean(told, "up"))));
    QVERIFY2(std::abs(cn0(told, "GPS") + 3) < 1, qPrintable(QString::number(cn0(told, "GPS"))));
    QVERIFY2(std::abs(cn0(told, "GLONASS") - 2) < 1,
             qPrintable(QString::number(cn0(told, "GLONASS"))));
    QVERIFY(std::abs(cn0(told, "Galileo")) < 1);
    // The dropped ones are the reference's alone; any other satellite only one of them has is
    // one it acquired sooner after its start, for a few epochs.
    for (const char *side : {"reference", "this"})
        for (const QJsonValue &v : told["only_in"].toObject()[side].toArray()) {
            const QString sat = v.toObject()["sat"].toString();
            const bool dropped =
                    QLatin1String(side) == "reference" && (sat == "G05" || sat == "R12");
            QVERIFY2(dropped || v.toObject()["epochs"].toInt() < matched / 2,
                     qPrintable(QString("%1 only in %2, %3 of %4 epochs")
                                        .arg(sat, side)
                                        .arg(v.toObject()["epochs"].toInt())
                                        .arg(matched)));
        }
}

} // namespace

class TstCompareCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // A log of `seconds` of the simulated `dialect`, with `extra` options.
    QString simulatedLog(const QString &name, const QString &dialect, const QStringList &extra,
                         int seconds) {
        QProcess p;
        p.setStandardOutputFile(dir_.filePath(name));
        p.start(gnss::link::test::simPath(),
                QStringList{"--dialect", dialect, "--stdout", "--speed", "1000", "--duration",
                            QString::number(seconds)} +
                        extra);
        p.closeWriteChannel();
        if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
        return dir_.filePath(name);
    }

private slots:
    void initTestCase() {
        if (gnss::link::test::simPath().isEmpty()) QSKIP("gnss-sim is not built");
        QVERIFY(dir_.isValid());
    }

    void logsOfOneSkyToldHowToDiffer() {
        const QString a = simulatedLog("a.nmea", "nmea", {}, 300);
        const QString b = simulatedLog("b.nmea", "nmea", kTold, 300);
        QVERIFY(!a.isEmpty() && !b.isEmpty());
        const Run r = cli({"compare", a, b, "--json"});
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QVERIFY2(j["matched_epochs"].toInt() >= 295, why(r));
        const QJsonArray receivers = j["receivers"].toArray();
        QCOMPARE(receivers.size(), 2);
        QCOMPARE(receivers[0].toObject()["name"].toString(), a);
        QCOMPARE(receivers[0].toObject()["dialect"].toString(), QString("nmea"));
        QVERIFY(!receivers[0].toObject().contains("difference_m")); // the reference
        checkTold(receivers[1].toObject(), j["matched_epochs"].toInt(), 0.02);

        // Without --json: a line per matched epoch, the words at the end.
        const Run lines = cli({"compare", a, b});
        QVERIFY2(lines.exitCode == 0, why(lines));
        const QList<QByteArray> out = lines.out.trimmed().split('\n');
        QCOMPARE(out.size(), j["matched_epochs"].toInt());
        const QJsonObject first = QJsonDocument::fromJson(out.last()).object();
        QCOMPARE(first["differences"].toArray().size(), 1);
        QVERIFY(first["differences"].toArray()[0].toObject().contains("horizontal"));
        QVERIFY2(lines.err.contains("epochs matched on UTC time") &&
                         lines.err.contains("GPS: C/N0 -3.0 dB"),
                 lines.err.constData());
    }

    void threeReceiversTheFirstIsTheReference() {
        const QString a = simulatedLog("c.nmea", "nmea", {}, 60);
        const QString b = simulatedLog("d.nmea", "nmea", {"--offset", "1,0,0"}, 60);
        const QString c = simulatedLog("e.nmea", "nmea", {"--offset", "0,2,0"}, 60);
        const Run r = cli({"compare", b, a, c, "--json"});
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonArray receivers = QJsonDocument::fromJson(r.out).object()["receivers"].toArray();
        QCOMPARE(receivers.size(), 3);
        // Each minus the first (b, 1 m east of the truth).
        QVERIFY(std::abs(mean(receivers[1].toObject(), "east") + 1) < 0.05);
        QVERIFY(std::abs(mean(receivers[2].toObject(), "east") + 1) < 0.05);
        QVERIFY(std::abs(mean(receivers[2].toObject(), "north") - 2) < 0.05);
    }

    // Two receivers on pseudo-terminals at speeds of their own, found by baud detection; the
    // numbers agree with the logs'. Without noise: started apart, their noise would not cancel,
    // and on a loaded machine (fewer epochs matched) its mean alone passed the tolerance.
    void liveReceiversAtTheirOwnSpeeds() {
        SimProcess a({"--dialect", "nmea", "--baud", "38400", "--start", "now", "--noise", "0"});
        SimProcess b(QStringList{"--dialect", "nmea", "--baud", "57600", "--start", "now",
                                 "--noise", "0"} +
                     kTold);
        if (!a.ok() || !b.ok()) QSKIP("no pseudo-terminals");
        const Run r = cli(
                {"compare", "--port", a.device, "--port", b.device, "--duration", "12", "--json"});
        QVERIFY2(r.exitCode == 0, why(r));
        QVERIFY2(r.err.contains("baud 38400 found") && r.err.contains("baud 57600 found"), why(r));
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QVERIFY2(j["matched_epochs"].toInt() >= 8, why(r));
        const QJsonArray receivers = j["receivers"].toArray();
        QVERIFY(receivers[0].toObject()["name"].toString().contains(a.device));
        checkTold(receivers[1].toObject(), j["matched_epochs"].toInt(), 0.06);
    }

    // An NV08C-RTK and a GeoS-5, each at a speed of its own, found by baud detection, reporting
    // the truth (--noise 0) of one sky (one --start), the GeoS-5 told to differ: the numbers
    // are what it was told, within 5 cm and 1 dB.
    void anNv08cAndAGeoS5ToldHowToDiffer() {
        // One fixed start: the same sky whatever the time of day the test runs at (G05 and R12
        // up), both at the same UTC.
        SimProcess a(
                {"--dialect", "nvs", "--baud", "38400", "--start", "10:00:05", "--noise", "0"});
        SimProcess b(QStringList{"--dialect", "geostar", "--baud", "57600", "--start", "10:00:05",
                                 "--noise", "0"} +
                     kTold);
        if (!a.ok() || !b.ok()) QSKIP("no pseudo-terminals");
        const Run r = cli(
                {"compare", "--port", a.device, "--port", b.device, "--duration", "10", "--json"});
        QVERIFY2(r.exitCode == 0, why(r));
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QVERIFY2(j["matched_epochs"].toInt() >= 5, why(r));
        const QJsonArray receivers = j["receivers"].toArray();
        QCOMPARE(receivers[0].toObject()["dialect"].toString(), QString("nvs"));
        // Each named by its model (its probe's answer) and its port.
        QCOMPARE(receivers[1].toObject()["dialect"].toString(), QString("geostar"));
        QVERIFY2(receivers[0].toObject()["name"].toString().startsWith("NV08C") &&
                         receivers[0].toObject()["name"].toString().contains(a.device),
                 why(r));
        QVERIFY2(receivers[1].toObject()["name"].toString().contains(b.device), why(r));
        const QJsonObject told = receivers[1].toObject();
        QVERIFY2(std::abs(mean(told, "east") - 0.3) < 0.05, why(r));
        QVERIFY2(std::abs(mean(told, "north") + 0.2) < 0.05, why(r));
        QVERIFY2(std::abs(mean(told, "up") - 0.5) < 0.05, why(r));
        QVERIFY2(std::abs(cn0(told, "GPS") + 3) < 1, why(r));
        QVERIFY2(std::abs(cn0(told, "GLONASS") - 2) < 1, why(r));
        QStringList onlyReference;
        for (const QJsonValue &v : told["only_in"].toObject()["reference"].toArray())
            onlyReference << v.toObject()["sat"].toString();
        QVERIFY2(onlyReference.contains("G05") || onlyReference.contains("R12"), why(r));
    }

    void refusals() {
        Run r = cli({"compare", "--sim", "nvs"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("two sources or more"));
        r = cli({"compare", "/nonexistent/a.nmea", "/nonexistent/b.nmea"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("/nonexistent/a.nmea"));
        r = cli({"compare", "--tcp", "nohostport", "--sim", "nvs"});
        QCOMPARE(r.exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TstCompareCli)
#include "tst_compare_cli.moc"
