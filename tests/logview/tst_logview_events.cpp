// Events and range statistics of a generated log whose faults are known: fix changes, a gap, a
// receiver reset, a checksum-error burst, junk, time marks, jamming on and off, base station
// changes, with and without a date (across midnight).
#include "logview/range_stats.h"
#include "logview_files.h"
#include "scenario_log.h"

#include <QRegularExpression>

#include <cmath>
#include <map>

using namespace gnss;
using namespace gnss::logview;

class TstLogviewEvents : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    DialectRegistry registry_ = makeBuiltinRegistry();

    std::string write(const test::Scenario &sc, const char *name) {
        const std::string path = dir_.filePath(name).toStdString();
        test::writeFile(path, test::scenarioLog(sc));
        return path;
    }

private slots:
    void eventsOfAKnownLog_data() {
        QTest::addColumn<bool>("withDate");
        QTest::addColumn<int>("start");
        QTest::newRow("dated") << true << 36000;
        QTest::newRow("no date, across midnight") << false << 86400 - 200;
    }
    void eventsOfAKnownLog() {
        QFETCH(bool, withDate);
        QFETCH(int, start);
        test::Scenario sc;
        sc.withDate = withDate;
        sc.startSeconds = start;
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, write(sc, "events.nmea")));
        QCOMPARE(view.epochCount(), std::size_t(600));
        std::map<EventKind, int> kinds;
        for (const LogEvent &e : view.events()) ++kinds[e.kind];
        QCOMPARE(kinds[EventKind::FixChange], 5);
        QCOMPARE(kinds[EventKind::Gap], 1);
        QCOMPARE(kinds[EventKind::TimeJump], 1);
        QCOMPARE(kinds[EventKind::ChecksumErrors], 1);
        QCOMPARE(kinds[EventKind::TimeMark], 2);
        QCOMPARE(kinds[EventKind::Jamming], 2);
        QCOMPARE(kinds[EventKind::BaseStation], 2);
        QCOMPARE(kinds[EventKind::DialectChange], 3); // NVS, GeoStar, NVS again
        const auto events = view.events();
        for (const LogEvent &e : events) {
            if (e.kind == EventKind::Gap) QCOMPARE(e.epoch, std::uint64_t(300));
            if (e.kind == EventKind::TimeJump) QCOMPARE(e.epoch, std::uint64_t(370));
            if (e.kind == EventKind::ChecksumErrors) {
                QCOMPARE(e.epoch, std::uint64_t(320)); // epoch 350 of the scenario, after the gap
                QVERIFY(e.text.starts_with("3 sentences"));
            }
        }
        // Without a date, the midnight is a day later, not a step back.
        if (!withDate) {
            bool midnight = false;
            view.withRecords([&](std::span<const EpochRecord> r) {
                for (const auto &x : r) midnight |= x.has(kMidnight);
            });
            QVERIFY(midnight);
        }
        // Next/previous event from an epoch.
        QCOMPARE(view.nextEvent(0).value_or(0), std::size_t(10));
        QCOMPARE(view.previousEvent(10).has_value(), false);
        QCOMPARE(view.nextEvent(299).value_or(0), std::size_t(300));
        QCOMPARE(view.previousEvent(301).value_or(0), std::size_t(300));
        // CSV: a header and a line per event.
        const std::string csv = eventsCsv(events);
        QCOMPARE(std::count(csv.begin(), csv.end(), '\n'), std::ptrdiff_t(events.size() + 1));
    }

    void rangeStatistics_data() {
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("last");
        QTest::addColumn<int>("epochs");
        QTest::addColumn<int>("none");
        QTest::addColumn<int>("fix3d");
        QTest::addColumn<int>("fl");
        QTest::addColumn<int>("fixed");
        QTest::addColumn<double>("ttff");
        QTest::addColumn<double>("ttRtk");
        QTest::addColumn<double>("longestGap");
        QTest::newRow("whole log")
                << 0 << 599 << 600 << 15 << 315 << 100 << 170 << 10.0 << 200.0 << 31.0;
        QTest::newRow("RTK float only")
                << 100 << 199 << 100 << 0 << 0 << 100 << 0 << 0.0 << -1.0 << 0.0;
        QTest::newRow("the gap") << 290 << 310 << 21 << 0 << 0 << 0 << 21 << 0.0 << 0.0 << 31.0;
        QTest::newRow("after the reset")
                << 370 << 599 << 230 << 5 << 225 << 0 << 0 << 5.0 << -1.0 << 0.0;
    }
    void rangeStatistics() {
        QFETCH(int, first);
        QFETCH(int, last);
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, write({}, "stats.nmea")));
        const RangeStats s = view.stats(first, last);
        QTEST(int(s.epochs), "epochs");
        QTEST(int(s.perFix[int(FixType::None)]), "none");
        QTEST(int(s.perFix[int(FixType::Fix3D)]), "fix3d");
        QTEST(int(s.perFix[int(FixType::RtkFloat)]), "fl");
        QTEST(int(s.perFix[int(FixType::RtkFixed)]), "fixed");
        QFETCH(double, ttff);
        QFETCH(double, ttRtk);
        QFETCH(double, longestGap);
        QVERIFY(s.timeToFirstFixS);
        QCOMPARE(*s.timeToFirstFixS, ttff);
        if (ttRtk < 0)
            QVERIFY(!s.timeToRtkFixedS);
        else
            QCOMPARE(s.timeToRtkFixedS.value_or(-2), ttRtk);
        QCOMPARE(s.longestGapS, longestGap);
        QVERIFY(s.cep50 && *s.cep50 > 0 && *s.cep50 < 0.05);
        QVERIFY(*s.cep95 >= *s.cep50 && *s.drms2 > 0 && *s.drms2 < 0.1);
        QVERIFY(std::abs(s.maxHdop.value_or(0) - 0.8) < 1e-6);
        const double sum = s.availability(FixType::None) + s.availability(FixType::Fix3D) +
                           s.availability(FixType::RtkFloat) + s.availability(FixType::RtkFixed);
        QVERIFY(std::abs(sum - 100) < 1e-9);
        // Messages per address in the range.
        const auto msgs = view.messageStats(first, last);
        std::uint64_t gga = 0;
        for (const auto &a : msgs)
            if (a.address == "GPGGA") gga = a.sentences;
        QCOMPARE(int(gga), s.epochs);
    }

    // The statistics' JSON says what the receiver printed and what the statistic can hold: the
    // HDOP the index keeps as a float is 0.8, not 0.800000011920929; 600 epochs' 0.1 s steps add up
    // in whole milliseconds; metres and degrees stop at a tenth of a millimetre.
    void statisticsJsonHasNoFloatNoise() {
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, write({}, "json.nmea")));
        const RangeStats s = view.stats(0, 599);
        std::string json;
        JsonWriter w(json);
        s.writeJson(w);
        QVERIFY2(json.find("\"max_hdop\":0.8,") != std::string::npos, json.c_str());
        QCOMPARE(s.durationS * 1000, std::round(s.durationS * 1000));
        static const QRegularExpression decimals(QStringLiteral("\\.([0-9]+)"));
        for (auto it = decimals.globalMatch(QString::fromStdString(json)); it.hasNext();) {
            const QString digits = it.next().captured(1);
            QVERIFY2(digits.size() <= 9,
                     qPrintable(digits + QStringLiteral(" in ") + QString::fromStdString(json)));
        }
    }

    // Times at the ends of the type (no decoder makes them now: ZDA keeps to four-digit years,
    // but an index is data) step and add up without overflowing: the steps stop at the limits,
    // and so does the elapsed time (the fuzz finding of 2026-12-07; UBSan fails this otherwise).
    void timesAtTheTypesEndsDoNotOverflowTheElapsedTime() {
        constexpr std::int64_t lo = kNoTime + 1, hi = std::numeric_limits<std::int64_t>::max();
        std::vector<EpochRecord> records(4);
        for (std::size_t i = 0; i < records.size(); ++i) {
            records[i].utcMs = (i % 2) ? hi : lo;
            records[i].flags = kDateKnown;
        }
        const RangeStats s = rangeStats(records, 0, records.size() - 1, false);
        QCOMPARE(s.epochs, std::uint64_t(4));
        QCOMPARE(s.durationS, static_cast<double>(hi) / 1000.0);
        QCOMPARE(*s.startMs, lo);
        QCOMPARE(*s.endMs, hi);
    }

    // CEP of known positions: a square of side 2 m around a point has every point at 1.414 m.
    void spreadOfKnownPositions() {
        std::vector<double> lats, lons;
        const double lat0 = 55.0, m = 1.0 / 111'000.0;
        for (int i = 0; i < 4; ++i) {
            lats.push_back(lat0 + ((i & 1) ? m : -m));
            lons.push_back(37.0 + ((i & 2) ? m : -m) / std::cos(lat0 * M_PI / 180));
        }
        const Spread s = horizontalSpread(lats, lons);
        QVERIFY(std::abs(s.cep50 - 1.414) < 0.02);
        QVERIFY(std::abs(s.drms2 - 2 * 1.414) < 0.04);
        QVERIFY(std::abs(s.meanLat - lat0) < 1e-9);
    }
};

QTEST_APPLESS_MAIN(TstLogviewEvents)
#include "tst_logview_events.moc"
