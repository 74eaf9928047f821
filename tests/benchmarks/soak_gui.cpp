// The GUI soak: the real MainWindow (as tests/support/laptop_window.h builds it) with every
// dock floating and shown, the charts showing every series and the sky plot its tracks, on a
// SoakTransport in place of the built-in simulator. A sampler on a 50 ms timer prints the table
// at every --every simulated minutes and sends a command through the command queue every 10
// simulated seconds (a poll and a setting in turn).
#include "soak_gui.h"

#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "gui/main_window.h"
#include "link/connection.h"
#include "models/console_model.h"
#include "models/message_stats_model.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
#include "models/time_series_model.h"
#include "session/receiver_link.h"
#include "soak_probe.h"
#include "soak_transport.h"
#include "state/receiver_state.h"
#include "views/attitude_view.h"
#include "views/charts_view.h"
#include "views/deviation_view.h"
#include "views/sky_plot_view.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLineSeries>
#include <QPointer>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace gnss::soak {
namespace {

constexpr qint64 kKeepRawBytes = 64 * 1024;    // ConsoleModel's raw buffer (console_model.cpp)
constexpr qint64 kTrackPointsCap = 30 * 6 + 1; // 30 min window, a point every 10 s
constexpr double kCommandEverySeconds = 10;

struct Window {
    QTemporaryDir dir;
    DialectRegistry registry = makeBuiltinRegistry();
    link::TransportFactory transports = app::makeTransportFactory(gnss::sim::builtinSimulators());
    QSettings settings{dir.filePath("settings.ini"), QSettings::IniFormat};
    QPointer<SoakTransport> transport;
    std::unique_ptr<app::MainWindow> w;

    Window() {
        transports.add(link::SourceSpec::Kind::Simulator,
                       [this](const link::SourceSpec &, QString *) {
                           auto t = std::make_unique<SoakTransport>(registry);
                           transport = t.get();
                           return std::unique_ptr<link::Transport>(std::move(t));
                       });
        w = std::make_unique<app::MainWindow>(registry, transports, &settings);
        w->resize(1280, 800);
        w->show();
        // Every dock on screen at once: floating, each its own window.
        int i = 0;
        for (const QString &name : w->dockNames()) {
            QDockWidget *d = w->dock(name + QStringLiteral("Dock"));
            if (!d) continue;
            d->setFloating(true);
            d->resize(520, 400);
            d->move(40 * (i % 10), 30 * (i % 10));
            d->show();
            ++i;
        }
        if (auto *charts = w->findChild<ui::ChartsView *>()) {
            QStringList all;
            for (int s = 0; s < ui::TimeSeriesModel::SeriesCount; ++s)
                all << ui::TimeSeriesModel::key(ui::TimeSeriesModel::Series(s));
            charts->setCheckedSeries(all);
        }
        if (auto *sky = w->findChild<ui::SkyPlotView *>()) sky->setShowTracks(true);
    }
};

std::vector<ListSize> listSizes(Window &win) {
    app::MainWindow &w = *win.w;
    std::vector<ListSize> out;
    auto add = [&](const char *name, long long size, long long cap) {
        out.push_back({QString::fromLatin1(name), size, cap});
    };
    auto *console = w.findChild<ui::ConsoleModel *>();
    add("console_rows", console ? console->rowCount() : -1, ui::ConsoleModel::kMaxLines);
    add("console_raw_bytes", console ? console->raw().size() : -1, kKeepRawBytes);

    auto *charts = w.findChild<ui::ChartsView *>();
    long long samples = 0, drawn = 0;
    long long sampleCap = charts ? (long long)charts->seriesModel()->capacity() : -1;
    if (charts)
        for (int s = 0; s < ui::TimeSeriesModel::SeriesCount; ++s) {
            const auto series = ui::TimeSeriesModel::Series(s);
            samples = std::max(samples, (long long)charts->seriesModel()->samples(series).size());
            if (QLineSeries *l = charts->lineSeries(series))
                drawn = std::max(drawn, (long long)l->count());
        }
    add("chart_samples_max", samples, sampleCap);
    add("chart_points_max", drawn, ui::ChartsView::kMaxPointsPerLine + 2);

    ui::SatelliteModel *sats = w.satelliteModel();
    long long trackMax = 0, trackTotal = 0;
    for (const ui::SatelliteRow &r : sats->rows())
        if (const auto *t = sats->track(r)) {
            trackMax = std::max(trackMax, (long long)t->size());
            trackTotal += (long long)t->size();
        }
    add("satellite_rows", sats->rowCount(), SoakSky::kPoolSize);
    add("track_points_max", trackMax, kTrackPointsCap);
    add("track_points_all", trackTotal, kTrackPointsCap * SoakSky::kPoolSize);

    auto *deviation = w.findChild<ui::DeviationView *>();
    add("scatter_points", deviation ? (long long)deviation->scatter().size() : -1,
        deviation ? deviation->capacity() : -1);

    auto *stats = w.findChild<ui::MessageStatsModel *>();
    long long historyMax = 0;
    if (stats)
        for (const auto &r : stats->rows())
            historyMax = std::max(historyMax, (long long)r.history.size());
    add("stats_rows", stats ? stats->rowCount() : -1, 100);
    add("stats_rate_history_max", historyMax, 200);

    link::Connection *c = w.link()->connection();
    add("command_history", c ? c->commands()->history().size() : -1,
        link::CommandQueue::kHistoryLimit);
    add("commands_pending", c ? c->commands()->pendingCount() : -1, -1);

    const ReceiverState &st = w.stateModel()->state();
    add("time_marks", (long long)st.timeMarks.size(), (long long)ReceiverState::kMaxTimeMarks);
    auto *attitude = w.findChild<ui::AttitudeView *>();
    auto *marks = attitude ? attitude->findChild<QTableWidget *>() : nullptr;
    add("attitude_rows", marks ? marks->rowCount() : -1, ui::AttitudeView::kMaxRows);
    add("state_reports", (long long)st.reports.size(), 50);
    return out;
}

} // namespace

int runGuiSoak(const SoakOptions &o) {
    Window win;
    const double endSeconds = o.hours * 3600.0;
    const double everySeconds = o.everyMinutes * 60.0;
    const double warmUpSeconds = std::min(o.warmUpHours, o.hours / 4) * 3600.0;
    win.w->connectAtStart({link::SourceSpec::Kind::Simulator, QStringLiteral("nvs")});
    if (!win.transport) {
        std::fprintf(stderr, "gnss-soak: the soak receiver was not opened\n");
        return 2;
    }
    win.transport->setEndSeconds(endSeconds);
    std::printf("gnss-soak: the main window offscreen on a %g Hz receiver with about 60 "
                "satellites, %g simulated hours, a sample every %g simulated minutes, growth "
                "measured after %g h\n",
                SoakSky::kRateHz, o.hours, o.everyMinutes, warmUpSeconds / 3600.0);

    SoakTable table;
    table.header(listSizes(win));
    QElapsedTimer real;
    real.start();
    double nextSample = 0, nextCommand = kCommandEverySeconds;
    bool warmDone = false;
    int commandsSent = 0, commandsRefused = 0;
    long long inViewSum = 0, inViewCount = 0;
    ProcessSample last;
    bool pass = false;
    QTimer sampler;
    sampler.setInterval(50);
    QObject::connect(&sampler, &QTimer::timeout, [&] {
        if (!win.transport) return;
        const double t = win.transport->simulatedSeconds();
        inViewSum += win.transport->satellitesInView();
        ++inViewCount;
        if (t >= nextCommand) {
            nextCommand += kCommandEverySeconds;
            link::Connection *c = win.w->link()->connection();
            if (c && c->commands()->pendingCount() == 0) {
                const QByteArray cmd = commandsSent % 2 ? QByteArrayLiteral("$PNVGRTK,ELGPS,5")
                                                        : QByteArrayLiteral("$PNVGVER");
                if (win.w->link()->send(cmd))
                    ++commandsSent;
                else
                    ++commandsRefused;
            }
        }
        if (!warmDone && t >= warmUpSeconds) {
            warmDone = true;
            table.endWarmUp(sampleSelf());
        }
        if (t >= nextSample || t >= endSeconds) {
            nextSample += everySeconds;
            last = sampleSelf();
            table.row(t / 3600.0, double(real.elapsed()) / 1000.0, last, listSizes(win));
        }
        if (t >= endSeconds) {
            sampler.stop();
            const double secs = double(real.elapsed()) / 1000.0;
            std::printf("simulated %.2f h in %.0f s real: %.0fx real time, %.0f epochs/s; "
                        "satellites in view %.1f on average; commands sent %d (%d refused); "
                        "CPU %.0f s\n",
                        t / 3600.0, secs, t / secs, t * SoakSky::kRateHz / secs,
                        inViewCount ? double(inViewSum) / double(inViewCount) : 0.0, commandsSent,
                        commandsRefused, last.cpuSeconds);
            pass = table.verdict(last, o.limitMb);
            QCoreApplication::quit();
        }
    });
    sampler.start();
    QApplication::exec();
    return pass ? 0 : 1;
}

} // namespace gnss::soak
