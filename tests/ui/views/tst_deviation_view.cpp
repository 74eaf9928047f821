// PositionScatter and DeviationView: metres east/north on the WGS-84 tangent plane, CEP50/CEP95
// as nearest-rank percentiles and 2DRMS against hand-computed figures, the bounded buffer, a
// typed reference, and the figures shown by the view.
#include "models/position_scatter.h"
#include "models/receiver_state_model.h"
#include "screenshot.h"
#include "views/deviation_view.h"

#include <QLabel>
#include <QPushButton>
#include <QRandomGenerator>
#include <QTest>

#include <cmath>
#include <numbers>

using namespace gnss;
using namespace gnss::ui;

namespace {

constexpr double kA = 6378137.0;
constexpr double kDeg = std::numbers::pi / 180.0;

// Degrees of longitude for `metres` east on the equator (N = a there).
double eastDegAtEquator(double metres) {
    return metres / (kA * kDeg);
}

QString text(const QWidget &w, const char *name) {
    auto *l = w.findChild<QLabel *>(QString::fromLatin1(name));
    return l ? l->text() : QString("<missing %1>").arg(name);
}

ReceiverState at(double lat, double lon, FixType fix) {
    ReceiverState st;
    st.epoch.lat = lat;
    st.epoch.lon = lon;
    st.epoch.fix = fix;
    return st;
}

} // namespace

class TstDeviationView : public QObject {
    Q_OBJECT
private slots:
    void eastNorthOnTheEllipsoid() {
        double e = 0, n = 0;
        // On the equator: east uses N = a, north the meridian radius a(1-e²).
        PositionScatter::toEastNorth(0, 0, 1e-5, 1e-5, e, n);
        QVERIFY(std::fabs(e - 1.1131949) < 1e-6);
        QVERIFY(std::fabs(n - 1.1057427) < 1e-6);
        // At 47.4° N one arc-second of latitude is about 30.88 m, of longitude about 20.97 m.
        PositionScatter::toEastNorth(47.4, 9.6, 47.4 + 1 / 3600.0, 9.6 + 1 / 3600.0, e, n);
        QVERIFY(std::fabs(n - 30.88) < 0.01);
        QVERIFY(std::fabs(e - 20.97) < 0.01);
        // Across the antimeridian it is the short way round.
        PositionScatter::toEastNorth(0, 179.99999, 0, -179.99999, e, n);
        QVERIFY(std::fabs(e - 2.2263898) < 1e-6);
    }

    void percentileIsNearestRank() {
        std::vector<double> v;
        for (int i = 20; i >= 1; --i) v.push_back(i);
        QCOMPARE(PositionScatter::percentile(v, 0.50), 10.0); // ceil(0.50*20) = 10th
        QCOMPARE(PositionScatter::percentile(v, 0.95), 19.0); // ceil(0.95*20) = 19th
        QCOMPARE(PositionScatter::percentile({3.0}, 0.95), 3.0);
        QCOMPARE(PositionScatter::percentile({}, 0.5), 0.0);
    }

    void cepAnd2drmsAgainstHandFigures() {
        // 20 points 1..20 m east of a reference on the equator.
        PositionScatter s;
        s.setReference(0.0, 0.0);
        for (int i = 1; i <= 20; ++i) s.add(0.0, eastDegAtEquator(i), FixType::RtkFixed);
        const auto &st = s.stats();
        QCOMPARE(st.count, std::size_t(20));
        QVERIFY(std::fabs(st.cep50 - 10.0) < 1e-6);
        QVERIFY(std::fabs(st.cep95 - 19.0) < 1e-6);
        // sx = sqrt((1²+...+20²)/20) = sqrt(143.5), sy = 0.
        QVERIFY(std::fabs(st.drms2 - 2.0 * std::sqrt(143.5)) < 1e-6);
        QVERIFY(std::fabs(st.meanEast - 10.5) < 1e-6);
        QVERIFY(std::fabs(st.meanNorth) < 1e-9);
        QVERIFY(std::fabs(st.maxError - 20.0) < 1e-6);
    }

    void aboutTheMeanTheFiguresAreTheSpread() {
        // Four points 1 m N/S/E/W of (47.4, 9.6): centre is their mean, every error 1 m,
        // sx = sy = sqrt(1/2), 2DRMS = 2.
        double e1 = 0, n1 = 0;
        PositionScatter::toEastNorth(47.4, 9.6, 47.4 + 1e-5, 9.6 + 1e-5, e1, n1);
        const double dLat = 1e-5 / n1, dLon = 1e-5 / e1; // degrees per metre here
        PositionScatter s;
        s.add(47.4 + dLat, 9.6, FixType::Fix3D);
        s.add(47.4 - dLat, 9.6, FixType::Fix3D);
        s.add(47.4, 9.6 + dLon, FixType::Dgnss);
        s.add(47.4, 9.6 - dLon, FixType::Dgnss);
        const auto &st = s.stats();
        QVERIFY(std::fabs(st.centreLat - 47.4) < 1e-12);
        QVERIFY(std::fabs(st.centreLon - 9.6) < 1e-12);
        QVERIFY(std::fabs(st.cep50 - 1.0) < 1e-6);
        QVERIFY(std::fabs(st.cep95 - 1.0) < 1e-6);
        QVERIFY(std::fabs(st.sdEast - std::sqrt(0.5)) < 1e-6);
        QVERIFY(std::fabs(st.drms2 - 2.0) < 1e-6);
        QCOMPARE(int(s.points().back().fix), int(FixType::Dgnss));
    }

    void keepsOnlyTheNewestN() {
        PositionScatter s(5);
        for (int i = 1; i <= 8; ++i) s.add(0.0, eastDegAtEquator(i), FixType::Fix3D);
        QCOMPARE(s.size(), std::size_t(5));
        s.setReference(0.0, 0.0);
        QVERIFY(std::fabs(s.points().front().east - 4.0) < 1e-6);
        s.setCapacity(2);
        QCOMPARE(s.size(), std::size_t(2));
        QVERIFY(std::fabs(s.points().front().east - 7.0) < 1e-6);
    }

    void degreesAreParsedWithHemispheres() {
        QCOMPARE(*DeviationView::parseDegrees("55.75 N", true), 55.75);
        QCOMPARE(*DeviationView::parseDegrees("33.9s", true), -33.9);
        QCOMPARE(*DeviationView::parseDegrees("-37.6", false), -37.6);
        QCOMPARE(*DeviationView::parseDegrees("37,6° W", false), -37.6);
        QVERIFY(!DeviationView::parseDegrees("91", true));
        QVERIFY(!DeviationView::parseDegrees("12 E", true));
        QVERIFY(!DeviationView::parseDegrees("abc", false));
    }

    void theViewShowsTheFiguresAndResets() {
        ReceiverStateModel model;
        DeviationView view(&model);
        QCOMPARE(view.capacity(), 3600);
        QCOMPARE(text(view, "deviationCep50"), QString(QChar(0x2014)));
        model.publish(at(0.0, 0.0, FixType::None)); // no fix: not a position
        view.setReference("0", "0");
        for (int i = 1; i <= 20; ++i)
            model.publish(at(0.0, eastDegAtEquator(i), FixType::RtkFixed));
        QTRY_COMPARE_WITH_TIMEOUT(text(view, "deviationCount"), QString("20"), 2000);
        QCOMPARE(text(view, "deviationCep50"), QString("10.000 m"));
        QCOMPARE(text(view, "deviationCep95"), QString("19.000 m"));
        QCOMPARE(text(view, "deviation2drms"), QString("23.958 m"));
        QCOMPARE(text(view, "deviationMeanOffset"), QString("10.500 m east, 0.000 m north"));
        QVERIFY(text(view, "deviationCentre").contains("0.00000000° N"));
        // Back to the mean: the spread about it.
        QVERIFY(view.setReference("", ""));
        QCOMPARE(text(view, "deviationCep50"), QString("4.500 m")); // |i - 10.5|, 10th of 20
        // A reference that is not one keeps the mean and says so.
        QVERIFY(!view.setReference("95 N", "10 E"));
        QCOMPARE(text(view, "deviationCep50"), QString("4.500 m")); // |i - 10.5|, 10th of 20
        view.findChild<QPushButton *>("deviationReset")->click();
        QCOMPARE(text(view, "deviationCount"), QString("0"));
        QCOMPARE(text(view, "deviationCep95"), QString(QChar(0x2014)));
    }

    void screenshotReadsWell() {
        ReceiverStateModel model;
        DeviationView view(&model);
        QRandomGenerator rng(8);
        const double lat0 = 47.40853048, lon0 = 9.62826005;
        const double mLat = 1.0 / 111200.0, mLon = 1.0 / 75300.0; // about a metre at 47.4° N
        for (int i = 0; i < 900; ++i) {
            FixType f = i < 150 ? FixType::Fix3D : i < 400 ? FixType::RtkFloat : FixType::RtkFixed;
            const double sigma = f == FixType::Fix3D ? 0.8 : f == FixType::RtkFloat ? 0.15 : 0.02;
            auto gauss = [&] {
                const double u1 = std::max(1e-12, rng.generateDouble()), u2 = rng.generateDouble();
                return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
            };
            model.publish(at(lat0 + gauss() * sigma * mLat, lon0 + gauss() * sigma * mLon, f));
        }
        view.resize(700, 720);
        view.refresh();
        test::checkScreenshot(view, "deviation_view.png");
    }
};

QTEST_MAIN(TstDeviationView)
#include "tst_deviation_view.moc"
