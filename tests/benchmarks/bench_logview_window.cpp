// The log viewer in the real main window (offscreen, 1280x800) on a big log: prints (does not
// assert) how soon the first epoch is on screen, when the index is ready, how long the docks take
// to follow the cursor to random epochs (seek, rebuild the state, publish, repaint), the GUI
// thread's CPU while playing at 100x, and the memory beyond the mapped file.
//
//   bench_logview_window [FILE] [--seeks N] [--play-seconds S] [--keep]
//
// Without FILE it writes gnss-loggen's 1 GB 10 Hz log to $TMPDIR and deletes it at the end.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "gui/log_viewer.h"
#include "gui/main_window.h"
#include "log_generator.h"
#include "models/receiver_state_model.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <random>

#include <sys/resource.h>

namespace {

double threadCpuSeconds() {
    rusage u{};
    ::getrusage(RUSAGE_THREAD, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

void runFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size() - 1) + 0.5))];
}

} // namespace

int main(int argc, char **argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QString path;
    int seeks = 200, playSeconds = 10;
    bool keep = false;
    const QStringList args = QApplication::arguments();
    for (int i = 1; i < args.size(); ++i) {
        if (args[i] == "--seeks" && i + 1 < args.size())
            seeks = args[++i].toInt();
        else if (args[i] == "--play-seconds" && i + 1 < args.size())
            playSeconds = args[++i].toInt();
        else if (args[i] == "--keep")
            keep = true;
        else
            path = args[i];
    }
    bool generated = false;
    if (path.isEmpty()) {
        const QByteArray tmp = qgetenv("TMPDIR");
        path = QString::fromLocal8Bit(tmp.isEmpty() ? "/tmp" : tmp) +
               "/bench_logview_window_1GB.nmea";
        std::printf("generating %s (1 GB, 10 Hz, GPS+GLONASS+Galileo+BeiDou)...\n",
                    qPrintable(path));
        std::fflush(stdout);
        if (!gnss::bench::writeLogFile(path.toStdString(), 1'000'000'000)) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
            return 1;
        }
        generated = true;
    }
    QTemporaryDir dir;
    QSettings settings(dir.filePath("settings.ini"), QSettings::IniFormat);
    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    const gnss::link::TransportFactory transports =
            gnss::app::makeTransportFactory(gnss::sim::builtinSimulators());
    gnss::app::MainWindow w(registry, transports, &settings);
    w.resize(1280, 800);
    w.show();
    runFor(300);
    const long anonBefore = gnss::bench::statusKb("RssAnon:");

    // Open: the first epoch on screen, then the index.
    QElapsedTimer clock;
    double firstMs = -1, readyMs = -1;
    QObject::connect(w.stateModel(), &gnss::ui::ReceiverStateModel::updated, &w, [&] {
        if (firstMs < 0 && w.stateModel()->epochCount() > 0) {
            QCoreApplication::processEvents(); // painted
            firstMs = double(clock.nsecsElapsed()) / 1e6;
        }
    });
    QObject::connect(w.logViewer(), &gnss::app::LogViewer::indexed, &w,
                     [&] { readyMs = double(clock.nsecsElapsed()) / 1e6; });
    clock.start();
    w.openLog(path);
    while (readyMs < 0 && !w.logViewer()->failed() && clock.elapsed() < 120000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
    gnss::app::LogViewer *viewer = w.logViewer();
    gnss::ui::LogCursor *cursor = viewer->cursor();
    const std::size_t n = cursor->epochCount();
    const double mb = double(viewer->view()->fileSize()) / 1e6;
    std::printf("log: %s, %.0f MB, %zu epochs\n", qPrintable(path), mb, n);
    std::printf("first epoch on screen:   %7.1f ms after open\n", firstMs);
    std::printf("index ready:             %7.1f ms after open (%.0f MB/s, GUI window included)\n",
                readyMs, mb / (readyMs / 1000));
    if (n == 0) return 1;
    runFor(500); // the whole log's message statistics arrive

    // Seek: every dock follows, painted.
    std::mt19937_64 rng(42);
    std::vector<double> seekMs, publishMs;
    for (int i = 0; i < seeks; ++i) {
        const std::size_t k = rng() % n;
        QElapsedTimer t;
        t.start();
        cursor->seek(k, true);
        QCoreApplication::processEvents();
        seekMs.push_back(double(t.nsecsElapsed()) / 1e6);
        publishMs.push_back(viewer->lastPublishMs());
    }
    std::printf("seek to a random epoch (%d): median %.1f ms, 99th percentile %.1f ms, max %.1f ms "
                "(state rebuilt and published: median %.1f ms)\n",
                seeks, percentile(seekMs, 0.5), percentile(seekMs, 0.99), percentile(seekMs, 1),
                percentile(publishMs, 0.5));

    // Play at 100x: the GUI thread's share of a core.
    cursor->seek(0, true);
    viewer->setSpeed(100);
    viewer->setPlaying(true);
    runFor(500);
    const double cpu0 = threadCpuSeconds();
    const std::size_t k0 = cursor->current();
    QElapsedTimer wall;
    wall.start();
    runFor(playSeconds * 1000);
    const double cpu = threadCpuSeconds() - cpu0, secs = double(wall.elapsed()) / 1000;
    viewer->setPlaying(false);
    std::printf("play at 100x for %.0f s: GUI thread %.0f %% of a core, %zu epochs passed "
                "(%.0f per second of log time at 10 Hz)\n",
                secs, 100 * cpu / secs, cursor->current() - k0,
                double(cursor->current() - k0) / secs);

    const long anonAfter = gnss::bench::statusKb("RssAnon:");
    const double indexMb = double(n) * 64 / 1e6;
    std::printf(
            "memory beyond the mapped file: %.0f MB (of which the index %.0f MB; before opening "
            "%.0f MB)\n",
            double(anonAfter - anonBefore) / 1024, indexMb, double(anonBefore) / 1024);
    w.closeLog();
    if (generated && !keep) std::remove(path.toLocal8Bit().constData());
    return 0;
}
