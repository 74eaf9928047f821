// Four receivers in the real main window (offscreen): each a 10 Hz receiver with about 60
// satellites in view (the soak's multi-constellation sky: GPS, GLONASS, Galileo, BeiDou; every
// other epoch of its 20 Hz output, so 10 epochs a second), every dock shown (floating, each its
// own window), the Compare dock open over all four. Prints:
//   1. the GUI process's CPU over --seconds of real time at 10 Hz (user + system, painting
//      included), as a share of one core;
//   2. resident memory over one simulated hour fed as fast as the GUI thread takes it: at the
//      end of a warm-up (the Compare window and the signal histories filled) and at the end,
//      and the growth between.
// A plain program: it prints its figures (issue 34 asks under 25 % of one core, under 10 MB of
// growth) and exits 1 when they are not met, 0 when they are; not a ctest suite.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "gui/main_window.h"
#include "link/transport.h"
#include "models/compare_model.h"
#include "models/receiver_session.h"
#include "models/receiver_state_model.h"
#include "soak_probe.h"
#include "soak_sky.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <memory>

using namespace gnss;

namespace {

constexpr double kRateHz = 10;

// A receiver of the soak's sky at 10 Hz: in real time (one epoch per 100 ms), or fast (as many
// epochs per pass of the event loop as 40 ms allow), up to an end.
class SkyTransport : public link::Transport {
public:
    SkyTransport(std::uint32_t seed, QObject *parent = nullptr) : Transport(parent), sky_(seed) {
        connect(&timer_, &QTimer::timeout, this, [this] { tick(); });
    }
    static inline bool fast = false;
    static inline double endSeconds = 1e9;

    bool open() override {
        timer_.start(100);
        clock_.start();
        setState(State::Open);
        return true;
    }
    void close() override {
        timer_.stop();
        setState(State::Closed);
    }
    QString description() const override { return QStringLiteral("10 Hz sky"); }
    int baud() const override { return 0; }
    bool setBaud(int) override { return true; }
    double seconds() const { return double(epoch_) / kRateHz; }

protected:
    bool writeBytes(const QByteArray &) override { return true; }

private:
    void tick() {
        QByteArray out;
        if (fast) {
            timer_.setInterval(0);
            QElapsedTimer pass;
            pass.start();
            while (pass.elapsed() < 10 && seconds() < endSeconds && out.size() < (1 << 20))
                out += sky_.epoch(2 * epoch_++);
        } else {
            // Epochs due by the real clock (a late timer catches up, never runs ahead).
            while (double(epoch_) < clock_.elapsed() * kRateHz / 1000.0)
                out += sky_.epoch(2 * epoch_++);
        }
        if (!out.isEmpty()) emit bytesReceived(out);
    }
    soak::SoakSky sky_;
    std::int64_t epoch_ = 0;
    QTimer timer_;
    QElapsedTimer clock_;
};

// The event loop, as the application runs it, for `seconds`.
void runFor(double seconds) {
    QEventLoop loop;
    QTimer::singleShot(int(seconds * 1000), &loop, &QEventLoop::quit);
    loop.exec();
}

// The event loop until `done` (looked at every 50 ms).
template <class Done> void runUntil(Done done) {
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done()) loop.quit();
    });
    poll.start(50);
    loop.exec();
}

} // namespace

int main(int argc, char **argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    qputenv("QT_LOGGING_RULES", "qt.qpa.*=false");
    QApplication app(argc, argv);
    double seconds = 30, hours = 1;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == "--seconds") seconds = args[i + 1].toDouble();
        if (args[i] == "--hours") hours = args[i + 1].toDouble();
    }
    QTemporaryDir dir;
    QSettings settings(dir.filePath("settings.ini"), QSettings::IniFormat);
    const DialectRegistry registry = makeBuiltinRegistry();
    link::TransportFactory transports = app::makeTransportFactory(gnss::sim::builtinSimulators());
    QList<SkyTransport *> skies;
    std::uint32_t seed = 0;
    transports.add(link::SourceSpec::Kind::Simulator, [&](const link::SourceSpec &, QString *) {
        auto t = std::make_unique<SkyTransport>(++seed);
        skies << t.get();
        return std::unique_ptr<link::Transport>(std::move(t));
    });
    app::MainWindow w(registry, transports, &settings);
    w.resize(1280, 800);
    w.show();
    w.connectReceiversAtStart({{link::SourceSpec::Kind::Simulator, "a"},
                               {link::SourceSpec::Kind::Simulator, "b"},
                               {link::SourceSpec::Kind::Simulator, "c"},
                               {link::SourceSpec::Kind::Simulator, "d"}});
    // Every dock on screen at once, the Compare dock among them.
    int i = 0;
    for (const QString &name : w.dockNames()) {
        QDockWidget *d = w.dock(name + QStringLiteral("Dock"));
        if (!d || name.startsWith(QLatin1String("log"))) continue;
        d->setFloating(true);
        d->resize(480, 360);
        d->move(30 * (i % 12), 24 * (i % 12));
        d->show();
        ++i;
    }
    runFor(5); // connected, first epochs, layouts settled
    const int inView = w.sessions()[0]->state()->state().epoch.satellites.size();
    const soak::ProcessSample before = soak::sampleSelf();
    const quint64 epochsBefore = w.sessions()[3]->state()->epochCount();
    QElapsedTimer wall;
    wall.start();
    runFor(seconds);
    const soak::ProcessSample after = soak::sampleSelf();
    const double wallSeconds = wall.elapsed() / 1000.0;
    const double cpu = 100.0 * (after.cpuSeconds - before.cpuSeconds) / wallSeconds;
    const double epochRate =
            double(w.sessions()[3]->state()->epochCount() - epochsBefore) / wallSeconds;
    std::printf("receivers: 4 at %.0f Hz, %d satellites in view each (GPS, GLONASS, Galileo, "
                "BeiDou), %d docks shown, Compare over 4\n",
                kRateHz, inView, i);
    std::printf("cpu: %.1f %% of one core over %.0f s (receiver 4: %.1f epochs/s, %zu matched "
                "epochs in the Compare window)\n",
                cpu, wallSeconds, epochRate, w.comparison()->matches().size());

    // One simulated hour, fast: resident memory every quarter of an hour; the growth is from the
    // half hour (the longest window any view keeps, the charts' and the sky tracks', filled) on.
    SkyTransport::fast = true;
    auto simulated = [&] {
        double s = 1e18;
        for (SkyTransport *t : skies) s = std::min(s, t->seconds());
        return s;
    };
    const double total = hours * 3600, warmUp = std::min(1800.0, total / 2);
    soak::ProcessSample warm, last = soak::sampleSelf();
    std::printf("memory: RSS %.1f MB at the start", last.rssMb);
    QElapsedTimer fastClock;
    fastClock.start();
    for (double at = 900; at <= total + 1; at += 900) {
        SkyTransport::endSeconds = at;
        runUntil([&] { return simulated() >= at; });
        runFor(0.5);
        last = soak::sampleSelf();
        if (at <= warmUp) warm = last;
        std::printf(", %.1f MB at %.0f min", last.rssMb, at / 60);
    }
    const double growth = last.rssMb - warm.rssMb;
    std::printf("\nmemory: growth %.1f MB from %.0f to %.0f simulated minutes (heap %.1f -> %.1f "
                "MB); %.1f simulated hours took %.0f s\n",
                growth, warmUp / 60, total / 60, warm.heapMb, last.heapMb, hours,
                fastClock.elapsed() / 1000.0);
    const bool ok = cpu < 25 && growth < 10;
    std::printf("%s (asked: under 25 %% of one core, under 10 MB growth)\n", ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}
