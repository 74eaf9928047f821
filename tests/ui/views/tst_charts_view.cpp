// ChartsView and TimeSeriesModel: values taken per series from a state, rolling-window trimming
// and the capacity bound, gaps for missing values, series picking, and redraw on the timer only.
#include "models/receiver_state_model.h"
#include "models/time_series_model.h"
#include "screenshot.h"
#include "views/charts_view.h"

#include <QCategoryAxis>
#include <QChartView>
#include <QLineSeries>
#include <QSpinBox>
#include <QTest>

#include <cmath>

using namespace gnss;
using namespace gnss::ui;
using TS = TimeSeriesModel;

namespace {

SatelliteInView sat(Constellation c, int prn, std::optional<int> snr, bool used) {
    SatelliteInView s;
    s.sat = {c, prn};
    s.snr = snr;
    s.used = used;
    return s;
}

ReceiverState sampleState(double phase = 0.0) {
    ReceiverState st;
    Epoch &e = st.epoch;
    e.fix = FixType::RtkFixed;
    e.satsUsed = 12;
    e.hdop = 0.8;
    e.pdop = 1.4;
    e.altMsl = 403.995 + 0.02 * std::sin(phase);
    e.sogKnots = 1.0;
    e.satellites = {sat(Constellation::Gps, 5, 40, true), sat(Constellation::Gps, 7, 44, true),
                    sat(Constellation::Gps, 9, std::nullopt, false),
                    sat(Constellation::Glonass, 3, 30, true),
                    sat(Constellation::Galileo, 11, 38 + int(3 * std::sin(phase)), true)};
    st.rtk.seen = true;
    st.rtk.sdLat = 0.005;
    st.rtk.sdLon = 0.004;
    st.rtk.sdHeight = 0.009 + 0.002 * std::cos(phase);
    st.rtk.baseToRover.length = 4769.223;
    return st;
}

const QDateTime t0 = QDateTime(QDate(2026, 5, 31), QTime(15, 35, 0), Qt::UTC);

} // namespace

class TstChartsView : public QObject {
    Q_OBJECT
private slots:
    void eachSeriesTakesItsValueFromTheState() {
        const ReceiverState st = sampleState();
        QCOMPARE(*TS::valueOf(TS::SatsUsed, st), 12.0);
        QCOMPARE(*TS::valueOf(TS::Hdop, st), 0.8);
        QCOMPARE(*TS::valueOf(TS::Pdop, st), 1.4);
        QCOMPARE(*TS::valueOf(TS::FixKind, st), double(int(FixType::RtkFixed)));
        QCOMPARE(*TS::valueOf(TS::SnrGps, st), 42.0); // (40 + 44) / 2; no SNR is not a zero
        QCOMPARE(*TS::valueOf(TS::SnrGlonass, st), 30.0);
        QVERIFY(!TS::valueOf(TS::SnrBeiDou, st));
        QCOMPARE(*TS::valueOf(TS::SdHeight, st), 0.011);
        QCOMPARE(*TS::valueOf(TS::BaselineLength, st), 4769.223);
        QCOMPARE(*TS::valueOf(TS::Speed, st), 1852.0 / 3600.0);
        QCOMPARE(*TS::valueOf(TS::AltitudeMsl, st), 403.995);
    }

    void keysRoundTrip() {
        for (int i = 0; i < TS::SeriesCount; ++i) {
            const auto s = static_cast<TS::Series>(i);
            QVERIFY(!TS::label(s).isEmpty());
            QCOMPARE(*TS::fromKey(TS::key(s)), s);
        }
        QCOMPARE(TS::key(TS::SnrGalileo), QString("snr.Galileo"));
        QVERIFY(!TS::fromKey("nonsense"));
    }

    void missingValuesLeaveGapsNotZeros() {
        TS m;
        ReceiverState st; // nothing but the fix type
        m.append(st, t0);
        QCOMPARE(m.samples(TS::FixKind).size(), std::size_t(1));
        QCOMPARE(m.samples(TS::SatsUsed).size(), std::size_t(0));
        QCOMPARE(m.samples(TS::Hdop).size(), std::size_t(0));
        QCOMPARE(m.samples(TS::SnrGps).size(), std::size_t(0));
    }

    void theWindowDropsOlderSamples() {
        TS m;
        m.setWindowSeconds(60);
        for (int i = 0; i <= 120; ++i) m.append(sampleState(), t0.addSecs(i));
        const auto &d = m.samples(TS::SatsUsed);
        QCOMPARE(d.size(), std::size_t(61)); // t0+60 .. t0+120 s, both ends kept
        QCOMPARE(d.front().msecs, t0.addSecs(60).toMSecsSinceEpoch());
        QCOMPARE(d.back().msecs, t0.addSecs(120).toMSecsSinceEpoch());
        QCOMPARE(m.latestMsecs(), t0.addSecs(120).toMSecsSinceEpoch());
        // Shrinking the window trims at once.
        m.setWindowSeconds(10);
        QCOMPARE(m.samples(TS::SatsUsed).size(), std::size_t(11));
    }

    void theCapacityBoundsEverySeries() {
        TS m;
        m.setCapacity(100);
        for (int i = 0; i < 1000; ++i) m.append(sampleState(), t0.addMSecs(i * 50));
        QCOMPARE(m.samples(TS::Hdop).size(), std::size_t(100));
        QCOMPARE(m.samples(TS::Hdop).back().msecs, t0.addMSecs(999 * 50).toMSecsSinceEpoch());
    }

    void aClearedStateModelClearsTheSeries() {
        ReceiverStateModel model;
        TS m;
        m.attach(&model);
        model.publish(sampleState(), t0);
        model.publish(sampleState(), t0.addSecs(1));
        QCOMPARE(m.samples(TS::SatsUsed).size(), std::size_t(2));
        model.clear();
        QCOMPARE(m.samples(TS::SatsUsed).size(), std::size_t(0));
    }

    void chartsRedrawOnTheTimerNotPerEpoch() {
        ReceiverStateModel model;
        ChartsView view(&model);
        QLineSeries *line = view.lineSeries(TS::SatsUsed);
        QVERIFY(line);
        for (int i = 0; i < 20; ++i) model.publish(sampleState(i * 0.1), t0.addMSecs(i * 200));
        QCOMPARE(view.seriesModel()->samples(TS::SatsUsed).size(), std::size_t(20));
        QCOMPARE(line->count(), 0); // the epochs alone drew nothing
        QTRY_COMPARE_WITH_TIMEOUT(line->count(), 20, 3000);
        // Newest at x = 0, older to the left, in the window's unit (minutes for 10 min).
        QCOMPARE(line->at(19).x(), 0.0);
        QVERIFY(line->at(0).x() < 0.0);
        QCOMPARE(line->at(19).y(), 12.0);
    }

    void pickingSeriesShowsOnlyTheirCharts() {
        ReceiverStateModel model;
        ChartsView view(&model);
        QVERIFY(view.checkedSeries().contains("satsUsed"));
        QVERIFY(view.checkedSeries().contains("snr.GPS"));
        view.setCheckedSeries({"altitudeMsl", "sdLat", "sdHeight"});
        QCOMPARE(view.checkedSeries(), QStringList({"sdLat", "sdHeight", "altitudeMsl"}));
        QVERIFY(!view.lineSeries(TS::SatsUsed));
        QVERIFY(view.lineSeries(TS::AltitudeMsl));
        QVERIFY(view.lineSeries(TS::SdHeight));
        QVERIFY(view.chartView(TS::Altitude)->isVisibleTo(&view));
        QVERIFY(view.chartView(TS::Deviation)->isVisibleTo(&view));
        QVERIFY(!view.chartView(TS::Satellites)->isVisibleTo(&view));
        model.publish(sampleState(), t0);
        view.redraw();
        QCOMPARE(view.lineSeries(TS::AltitudeMsl)->count(), 1);
        QCOMPARE(view.lineSeries(TS::AltitudeMsl)->at(0).y(), 403.995);
    }

    void theWindowSpinSetsTheModelsWindow() {
        ReceiverStateModel model;
        ChartsView view(&model);
        QCOMPARE(view.windowMinutes(), 10);
        QCOMPARE(view.seriesModel()->windowSeconds(), 600.0);
        view.findChild<QSpinBox *>("chartsWindow")->setValue(2);
        QCOMPARE(view.seriesModel()->windowSeconds(), 120.0);
    }

    void longSeriesAreReducedButKeepTheirExtremes() {
        ReceiverStateModel model;
        ChartsView view(&model);
        view.setCheckedSeries({"hdop"});
        for (int i = 0; i < 6000; ++i) {
            ReceiverState st = sampleState();
            st.epoch.hdop = i == 3333 ? 9.9 : 0.8;
            model.publish(st, t0.addMSecs(i * 50));
        }
        view.redraw();
        QLineSeries *line = view.lineSeries(TS::Hdop);
        QVERIFY(line->count() <= ChartsView::kMaxPointsPerLine + 2);
        double top = 0;
        for (const QPointF &p : line->points()) top = std::max(top, p.y());
        QCOMPARE(top, 9.9);
    }

    void aDarkPaletteRepaintsTheCharts() {
        ReceiverStateModel model;
        ChartsView view(&model);
        for (int i = 0; i < 100; ++i) model.publish(sampleState(i * 0.1), t0.addMSecs(i * 200));
        QPalette dark;
        dark.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
        dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
        dark.setColor(QPalette::WindowText, QColor(0xe0, 0xe0, 0xe0));
        dark.setColor(QPalette::Text, QColor(0xe0, 0xe0, 0xe0));
        dark.setColor(QPalette::Mid, QColor(0x55, 0x55, 0x55));
        view.setPalette(dark);
        view.redraw();
        QChart *chart = view.chartView(TS::Dop)->chart();
        QCOMPARE(chart->backgroundBrush().color(), QColor(0x1e, 0x1e, 0x1e));
        QCOMPARE(chart->titleBrush().color(), QColor(0xe0, 0xe0, 0xe0));
        view.resize(900, 700);
        QTest::qWait(50); // let the charts lay out at the new size before grabbing
        // The fix axis names the fix types around the data and keeps that span after layout.
        auto *cat = qobject_cast<QCategoryAxis *>(
                view.chartView(TS::Fix)->chart()->axes(Qt::Vertical).value(0));
        QVERIFY(cat);
        QCOMPARE(cat->categoriesLabels(), QStringList({"DGNSS", "RTK float", "RTK fixed"}));
        QCOMPARE(cat->min(), 3.5);
        QCOMPARE(cat->max(), 6.5);
        QVERIFY(test::saveScreenshot(view.grab().toImage(), "charts_view_dark.png"));
    }

    void screenshotReadsWell() {
        ReceiverStateModel model;
        ChartsView view(&model);
        for (int i = 0; i < 600; ++i) {
            ReceiverState st = sampleState(i * 0.05);
            if (i < 100)
                st.epoch.fix = FixType::Fix3D;
            else if (i < 250)
                st.epoch.fix = FixType::RtkFloat;
            st.epoch.satsUsed = 12 + (i / 90) % 3;
            *st.epoch.hdop += 0.1 * std::sin(i * 0.02);
            model.publish(st, t0.addMSecs(i * 200));
        }
        view.resize(900, 900);
        view.redraw();
        test::checkScreenshot(view, "charts_view.png");
    }
};

QTEST_MAIN(TstChartsView)
#include "tst_charts_view.moc"
