// The CLI soak: gnss-sim (NV08C-RTK, internal base) on a TCP port of 127.0.0.1 at --speed,
// its PVT rate raised to --rate by a command sent before gnss-cli connects (the simulated
// receiver keeps its settings between clients), then `gnss-cli monitor` (its JSON read and
// counted here) or `gnss-cli record` (into a temporary directory) on it. The child's RSS and
// CPU come from /proc at every --every simulated minutes; the simulated time is the real time
// since gnss-cli started times --speed.
#include "soak_cli.h"

#include "core/sentence_builder.h"
#include "soak_probe.h"
#include "soak_sky_server.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QProcess>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace gnss::soak {
namespace {

QString binary(const SoakOptions &o, const QString &name) {
    if (!o.bin.isEmpty()) return QDir(o.bin).filePath(name);
    // The build tree: gnss-soak is in tests/benchmarks, gnss-cli in app/cli, gnss-sim in app/sim.
    const QDir here(QCoreApplication::applicationDirPath());
    const QString sub = name == QLatin1String("gnss-cli") ? QStringLiteral("app/cli")
                                                          : QStringLiteral("app/sim");
    return QDir::cleanPath(here.filePath(QStringLiteral("../../") + sub + QLatin1Char('/') + name));
}

int freePort() {
    QTcpServer s;
    s.listen(QHostAddress::LocalHost, 0);
    return s.serverPort();
}

// Sends one command to gnss-sim as a client and waits (20 s at most) for `expect` in its output.
bool configure(int port, const std::string &body, const QByteArray &expect) {
    QTcpSocket s;
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 20000) {
        s.connectToHost(QHostAddress::LocalHost, quint16(port));
        if (s.waitForConnected(1000)) break;
        QThread::msleep(100);
    }
    if (s.state() != QAbstractSocket::ConnectedState) return false;
    s.write(QByteArray::fromStdString(gnss::buildSentence(body)) + "\r\n");
    QByteArray got;
    while (clock.elapsed() < 20000 && !got.contains(expect)) {
        if (s.waitForReadyRead(200)) got += s.readAll();
        if (got.size() > (1 << 20)) got = got.right(4096);
    }
    s.disconnectFromHost();
    return got.contains(expect);
}

} // namespace

int runCliSoak(const SoakOptions &o) {
    const QString cli = binary(o, QStringLiteral("gnss-cli")),
                  simBin = binary(o, QStringLiteral("gnss-sim"));
    for (const QString &b : {cli, simBin})
        if (!QFileInfo(b).isExecutable()) {
            std::fprintf(stderr, "gnss-soak: %s not found (--bin DIR)\n", qPrintable(b));
            return 2;
        }
    const bool soakSky = o.sky == QLatin1String("soak");
    SkyServer server(o.speed);
    QProcess sim;
    int port = 0;
    if (soakSky) {
        if (!server.listen()) {
            std::fprintf(stderr, "gnss-soak: no port on 127.0.0.1 for the sky\n");
            return 2;
        }
        port = server.port();
    } else {
        port = freePort();
        sim.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        sim.start(simBin, {"--dialect", "nvs", "--internal-base", "--tcp", QString::number(port),
                           "--speed", QString::number(o.speed)});
        if (!sim.waitForStarted(20000)) {
            std::fprintf(stderr, "gnss-soak: gnss-sim did not start\n");
            return 2;
        }
        const std::string rate = "PNVGRTK,PVTRATE," + std::to_string(o.rateHz);
        if (!configure(port, rate, "PVTRATE," + QByteArray::number(o.rateHz))) {
            std::fprintf(stderr, "gnss-soak: gnss-sim did not take %s\n", rate.c_str());
            sim.kill();
            sim.waitForFinished(5000);
            return 2;
        }
    }

    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("soak.log"));
    QStringList args{o.cli, "--tcp", QStringLiteral("127.0.0.1:%1").arg(port)};
    if (o.cli == QLatin1String("record"))
        args << "--out" << out;
    else
        args << "--dialect" << (soakSky ? "nmea" : "nvs");
    QProcess child;
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    long long jsonLines = 0, ggaLines = 0, jsonBytes = 0;
    QByteArray tail;
    QObject::connect(&child, &QProcess::readyReadStandardOutput, [&] {
        QByteArray chunk = tail + child.readAllStandardOutput();
        jsonBytes += chunk.size() - tail.size();
        const qsizetype cut = chunk.lastIndexOf('\n') + 1;
        const QByteArray whole = chunk.left(cut);
        tail = chunk.mid(cut);
        jsonLines += whole.count('\n');
        ggaLines += whole.count("\"type\":\"GGA\"");
    });
    child.start(cli, args);
    if (!child.waitForStarted(20000)) {
        std::fprintf(stderr, "gnss-soak: gnss-cli did not start\n");
        sim.kill();
        sim.waitForFinished(5000);
        return 2;
    }
    const long long pid = child.processId();
    const double rateHz = soakSky ? SoakSky::kRateHz : double(o.rateHz);
    if (soakSky)
        std::printf("gnss-soak --cli %s: gnss-cli %s on gnss-soak's own sky (20 Hz, about 60 "
                    "satellites) at up to %gx, %g simulated hours, a sample every %g simulated "
                    "minutes\n",
                    qPrintable(o.cli), qPrintable(args.join(' ')), o.speed, o.hours,
                    o.everyMinutes);
    else
        std::printf("gnss-soak --cli %s: gnss-cli %s on gnss-sim --dialect nvs --speed %g, PVT "
                    "rate %d Hz (the NV08C-RTK's highest), %g simulated hours, a sample every %g "
                    "simulated minutes\n",
                    qPrintable(o.cli), qPrintable(args.join(' ')), o.speed, o.rateHz, o.hours,
                    o.everyMinutes);

    const double endSeconds = o.hours * 3600.0;
    const double warmUpSeconds = std::min(o.warmUpHours, o.hours / 4) * 3600.0;
    SoakTable table;
    auto lists = [&] {
        std::vector<ListSize> l;
        l.push_back(
                {QStringLiteral("out_MB"),
                 o.cli == QLatin1String("record") ? QFileInfo(out).size() >> 20 : jsonBytes >> 20,
                 -1});
        if (o.cli == QLatin1String("monitor")) {
            l.push_back({QStringLiteral("json_lines"), jsonLines, -1});
            l.push_back({QStringLiteral("gga_epochs"), ggaLines, -1});
        }
        if (!soakSky) {
            const ProcessSample s = samplePid(sim.processId());
            l.push_back({QStringLiteral("sim_rss_MB"), (long long)std::lround(s.rssMb), -1});
            l.push_back({QStringLiteral("sim_cpu_s"), (long long)std::lround(s.cpuSeconds), -1});
        }
        return l;
    };
    table.header(lists());
    QElapsedTimer real;
    real.start();
    double nextSample = 0;
    bool warmDone = false, pass = false;
    ProcessSample last;
    QTimer sampler;
    sampler.setInterval(20);
    QObject::connect(&sampler, &QTimer::timeout, [&] {
        const double t =
                soakSky ? server.simulatedSeconds() : double(real.elapsed()) / 1000.0 * o.speed;
        if (child.state() != QProcess::Running) {
            std::printf("gnss-cli ended early (exit %d): FAIL\n", child.exitCode());
            sampler.stop();
            QCoreApplication::exit(1);
            return;
        }
        if (!warmDone && t >= warmUpSeconds) {
            warmDone = true;
            table.endWarmUp(samplePid(pid));
        }
        if (t >= nextSample || t >= endSeconds) {
            nextSample += o.everyMinutes * 60.0;
            last = samplePid(pid);
            table.row(t / 3600.0, double(real.elapsed()) / 1000.0, last, lists());
        }
        if (t >= endSeconds) {
            sampler.stop();
            const double secs = double(real.elapsed()) / 1000.0;
            std::printf("simulated %.2f h in %.1f s real (%.0fx); gnss-cli CPU %.1f s\n",
                        t / 3600.0, secs, t / secs, last.cpuSeconds);
            if (o.cli == QLatin1String("monitor"))
                std::printf("%lld epochs decoded: %.1f%% of %g Hz x the simulated time (gnss-sim "
                            "drops what its client does not take; the soak's sky waits)\n",
                            ggaLines, 100.0 * double(ggaLines) / (t * rateHz), rateHz);
            pass = table.verdict(last, o.limitMb);
            QCoreApplication::exit(pass ? 0 : 1);
        }
    });
    sampler.start();
    const int code = QCoreApplication::exec();
    child.terminate();
    child.waitForFinished(20000);
    sim.terminate();
    sim.waitForFinished(20000);
    if (o.cli == QLatin1String("record"))
        std::printf("recorded %.1f MB (%s.idx %.1f MB)\n",
                    double(QFileInfo(out).size()) / 1048576.0,
                    qPrintable(QFileInfo(out).fileName()),
                    double(QFileInfo(out + ".idx").size()) / 1048576.0);
    return code;
}

} // namespace gnss::soak
