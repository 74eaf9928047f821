// A time-to-first-fix run followed epoch by epoch (the first position, 2D, 3D, DGNSS, RTK float
// and fixed; the fix left over from before the restart not counted; satellites and distance at
// the first 3D fix), and a campaign's statistics per kind of start with its JSON.
#include "core/json_writer.h"
#include "core/wgs84.h"
#include "qualify/ttff.h"
#include "state/epoch.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace gnss;
using namespace gnss::qualify;

namespace {

Epoch epoch(FixType fix, int sats = 8, double northM = 0) {
    Epoch e;
    e.fix = fix;
    if (fix != FixType::None) {
        e.lat = 55.75 + northM / wgs84::metresPerDegree(55.75).north;
        e.lon = 37.61;
    }
    e.satsUsed = sats;
    return e;
}

TtffRun fixedRun(ReceiverAction a, int i, double t) {
    TtffRun r;
    r.start = a;
    r.index = i;
    r.outcome = RunOutcome::Fixed;
    r.fix3d = t;
    return r;
}

} // namespace

class TstTtffRuns : public QObject {
    Q_OBJECT
private slots:
    void aRunRecordsEachFirst() {
        RunTracker t(ReceiverAction::ColdStart, 1);
        t.setReference(55.75, 37.61);
        t.add(epoch(FixType::Fix3D), 0.2); // the fix before the restart: not a first fix
        t.add(epoch(FixType::None), 1.0);
        t.add(epoch(FixType::Fix2D, 4), 20.0);
        QVERIFY(!t.fixed3d());
        t.add(epoch(FixType::Fix3D, 7, 12.0), 25.0);
        t.add(epoch(FixType::Dgnss), 30.0);
        t.add(epoch(FixType::RtkFloat), 40.0);
        t.add(epoch(FixType::RtkFixed), 55.0);
        const TtffRun &r = t.run();
        QCOMPARE(*r.position, 20.0);
        QCOMPARE(*r.fix2d, 20.0);
        QCOMPARE(*r.fix3d, 25.0);
        QCOMPARE(*r.satellitesAtFix, 7);
        QVERIFY(std::abs(*r.distanceM - 12.0) < 0.01);
        QCOMPARE(*r.dgnss, 30.0);
        QCOMPARE(*r.rtkFloat, 40.0);
        QCOMPARE(*r.rtkFixed, 55.0);
    }

    // A receiver that keeps its fix through a hot start: the first fix 3 s after the command.
    void aFixKeptThroughTheRestartCountsAfterThreeSeconds() {
        RunTracker t(ReceiverAction::HotStart, 1);
        t.add(epoch(FixType::Fix3D), 1.0);
        t.add(epoch(FixType::Fix3D), 2.0);
        QVERIFY(!t.fixed3d());
        t.add(epoch(FixType::Fix3D), 3.0);
        QCOMPARE(*t.run().fix3d, 3.0);
    }

    void statisticsPerKind() {
        std::vector<TtffRun> runs;
        for (int i = 1; i <= 10; ++i)
            runs.push_back(fixedRun(ReceiverAction::ColdStart, i, 30 + i));
        TtffRun timeout;
        timeout.start = ReceiverAction::ColdStart;
        timeout.index = 11;
        timeout.outcome = RunOutcome::TimedOut;
        runs.push_back(timeout);
        runs.push_back(fixedRun(ReceiverAction::HotStart, 1, 2));
        const auto stats = statsOf(runs);
        QCOMPARE(stats.size(), std::size_t(2));
        QVERIFY(stats[0].start == ReceiverAction::ColdStart);
        QCOMPARE(stats[0].runs, 11);
        QCOMPARE(stats[0].fixed, 10);
        QCOMPARE(stats[0].timeouts, 1);
        QCOMPARE(stats[0].ttff.mean, 35.5);
        QCOMPARE(stats[0].ttff.median, 35.5);
        QCOMPARE(stats[0].ttff.min, 31.0);
        QCOMPARE(stats[0].ttff.max, 40.0);
        QVERIFY(std::abs(stats[0].p90 - 39.1) < 1e-9);
        QVERIFY(stats[1].start == ReceiverAction::HotStart);

        std::string out;
        JsonWriter w(out);
        w.beginObject();
        writeCampaignJson(w, runs);
        w.endObject();
        const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(out)).object();
        QVERIFY2(!o.isEmpty(), out.c_str());
        const QJsonObject cold = o["starts"].toObject()["cold"].toObject();
        QCOMPARE(cold["runs"].toInt(), 11);
        QCOMPARE(cold["timeouts"].toInt(), 1);
        for (const char *k : {"mean", "median", "p95", "min", "max"})
            QVERIFY2(cold["ttff_s"].toObject().contains(k), k);
        QVERIFY(!o["starts"].toObject().contains("warm"));
        QCOMPARE(o["runs"].toArray().size(), 12);
        QCOMPARE(o["runs"].toArray()[10].toObject()["outcome"].toString(), QString("timeout"));
        QCOMPARE(o["runs"].toArray()[0].toObject()["ttff_s"].toDouble(), 31.0);
    }
};

QTEST_GUILESS_MAIN(TstTtffRuns)
#include "tst_ttff_runs.moc"
