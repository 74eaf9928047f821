// GUI cost at a 20 Hz receiver with 60 satellites in view: one epoch through the session into the
// models (decode, state, satellite model update), and painting the sky plot and signal levels.
// Prints each cost and what it means for the GUI thread at 20 epochs/s and 10 repaints/s.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "models/console_model.h"
#include "models/message_stats_model.h"
#include "models/model_feed.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
#include "views/deviation_view.h"
#include "views/signal_levels_view.h"
#include "views/sky_plot_view.h"

#include <QApplication>
#include <QImage>
#include <benchmark/benchmark.h>
#include <cstdio>

namespace {

struct Sys {
    const char *talker;
    int systemId, count, firstId, signalId;
};
constexpr Sys kSystems[] = {
        {"GP", 1, 16, 1, 1}, {"GL", 2, 14, 65, 1}, {"GA", 3, 14, 1, 7}, {"GB", 4, 16, 1, 1}};

// One 20 Hz epoch (60 satellites): RMC, GGA, GSA per system, GSV per system.
QByteArray epochBytes(int n) {
    QByteArray out;
    char b[200];
    const double s = n * 0.05;
    auto add = [&](const std::string &body) {
        out += QByteArray::fromStdString(gnss::buildSentence(body)) + "\r\n";
    };
    std::snprintf(b, sizeof b, "GNRMC,1200%05.2f,A,5550.6129,N,03732.2527,E,0.01,0.0,230394,,,R,V",
                  s);
    add(b);
    std::snprintf(b, sizeof b,
                  "GNGGA,1200%05.2f,5550.6129,N,03732.2527,E,4,40,0.5,180.0,M,14.4,M,1.0,0031", s);
    add(b);
    for (const Sys &sys : kSystems) {
        std::string gsa = "GNGSA,A,3";
        for (int i = 0; i < 12; ++i) gsa += i < 10 ? "," + std::to_string(sys.firstId + i) : ",";
        add(gsa + ",1.0,0.5,0.8," + std::to_string(sys.systemId));
        const int parts = (sys.count + 3) / 4;
        for (int p = 0; p < parts; ++p) {
            std::snprintf(b, sizeof b, "%sGSV,%d,%d,%02d", sys.talker, parts, p + 1, sys.count);
            std::string gsv = b;
            for (int k = p * 4; k < std::min(sys.count, p * 4 + 4); ++k) {
                std::snprintf(b, sizeof b, ",%02d,%02d,%03d,%02d", sys.firstId + k,
                              5 + (k * 11) % 85, (k * 37 + n) % 360, 30 + k % 20);
                gsv += b;
            }
            add(gsv + "," + std::to_string(sys.signalId));
        }
    }
    return out;
}

struct Fixture {
    gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    gnss::ui::ReceiverStateModel state;
    gnss::ui::SatelliteModel satellites;
    gnss::ui::MessageStatsModel messages;
    gnss::ui::ConsoleModel console;
    gnss::ui::ModelFeed session{registry, {&state, &satellites, &messages, &console}};
    gnss::StreamDecoder decoder{registry}; // the link's decoder, as in the application
    std::vector<QByteArray> epochs;
    Fixture() {
        session.setCounterSource(&decoder);
        for (int i = 0; i < 200; ++i) epochs.push_back(epochBytes(i));
        for (int i = 0; i < 10; ++i) feed(epochs[size_t(i)]);
        session.refresh();
    }
    void feed(const QByteArray &bytes) {
        session.noteBytes(bytes);
        decoder.feed(
                std::string_view(bytes.constData(), std::size_t(bytes.size())),
                [this](const gnss::SentenceEvent &ev) { session.consume(ev, decoder.dialect()); });
    }
};

Fixture &fixture() {
    static Fixture f;
    return f;
}

void BM_EpochIntoModels(benchmark::State &st) {
    Fixture &f = fixture();
    std::size_t i = 0;
    for (auto _ : st) {
        f.feed(f.epochs[i++ % f.epochs.size()]);
        if (i % 2 == 0) f.session.refresh(); // the session's 100 ms timer at 20 Hz
    }
    st.counters["satellites"] = f.satellites.rowCount();
}
BENCHMARK(BM_EpochIntoModels)->Unit(benchmark::kMicrosecond);

template <class View> void paintBench(benchmark::State &st) {
    Fixture &f = fixture();
    View view(&f.satellites);
    view.resize(600, 500);
    QImage img(view.size(), QImage::Format_ARGB32_Premultiplied);
    for (auto _ : st) {
        view.render(&img);
        benchmark::DoNotOptimize(img.bits());
    }
}
void BM_PaintSkyPlot(benchmark::State &st) {
    paintBench<gnss::ui::SkyPlotView>(st);
}
void BM_PaintSignalLevels(benchmark::State &st) {
    paintBench<gnss::ui::SignalLevelsView>(st);
}
BENCHMARK(BM_PaintSkyPlot)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaintSignalLevels)->Unit(benchmark::kMicrosecond);

// The deviation plot with its default 3600 positions kept.
void BM_PaintDeviation(benchmark::State &st) {
    Fixture &f = fixture();
    gnss::ui::DeviationView view(&f.state);
    for (int i = 0; i < 3600; ++i) f.feed(f.epochs[size_t(i) % f.epochs.size()]);
    view.resize(600, 500);
    QImage img(view.size(), QImage::Format_ARGB32_Premultiplied);
    for (auto _ : st) {
        view.render(&img);
        benchmark::DoNotOptimize(img.bits());
    }
}
BENCHMARK(BM_PaintDeviation)->Unit(benchmark::kMicrosecond);

// Prints the GUI-thread budget from the measured costs.
class BudgetReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run> &runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run &r : runs) {
            const double us = r.GetAdjustedRealTime(); // microseconds (the unit above)
            if (r.benchmark_name().find("EpochIntoModels") != std::string::npos) epochUs_ = us;
            if (r.benchmark_name().find("PaintSkyPlot") != std::string::npos) skyUs_ = us;
            if (r.benchmark_name().find("PaintSignalLevels") != std::string::npos) barsUs_ = us;
            if (r.benchmark_name().find("PaintDeviation") != std::string::npos) deviationUs_ = us;
        }
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        const double perSecondUs = epochUs_ * 20 + (skyUs_ + barsUs_) * 10 + deviationUs_ * 4;
        std::printf("\nGUI thread at 20 Hz, 60 satellites: epoch into models %.0f us x 20/s + sky "
                    "%.0f us "
                    "and signals %.0f us x 10 repaints/s + deviation (3600 points) %.0f us x 4/s = "
                    "%.1f%% of one core\n",
                    epochUs_, skyUs_, barsUs_, deviationUs_, perSecondUs / 1e4);
    }

private:
    double epochUs_ = 0, skyUs_ = 0, barsUs_ = 0, deviationUs_ = 0;
};

} // namespace

int main(int argc, char **argv) {
    qputenv("QT_QPA_PLATFORM",
            qgetenv("QT_QPA_PLATFORM").isEmpty() ? "offscreen" : qgetenv("QT_QPA_PLATFORM"));
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    BudgetReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();
    return 0;
}
