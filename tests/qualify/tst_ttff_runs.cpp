// A time-to-first-fix run followed epoch by epoch (the first position, 2D, 3D, DGNSS, RTK float
// and fixed; the fix left over from before the restart not counted; satellites and distance at
// the first 3D fix), and a campaign's statistics per kind of start with its JSON.
#include "core/json_writer.h"
#include "core/wgs84.h"
#include "qualify/limits.h"
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

    // A limit as the user types it, and what is refused with the reason.
    void limitsAreParsed_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("canonical"); // empty: refused
        QTest::addColumn<QString>("why");       // part of the refusal
        QTest::newRow("mean") << "cold:mean<=60"
                              << "cold:mean<=60"
                              << "";
        QTest::newRow("spaces, seconds") << " hot p95 <= 12.5 s"
                                         << "hot:p95<=12.5"
                                         << "";
        QTest::newRow("sign") << "warm:max≤40"
                              << "warm:max<=40"
                              << "";
        QTest::newRow("median") << "warm:median<=38"
                                << "warm:median<=38"
                                << "";
        QTest::newRow("p90") << "cold:p90<=90"
                             << "cold:p90<=90"
                             << "";
        QTest::newRow("no operator") << "cold:mean=60"
                                     << ""
                                     << "no <=";
        QTest::newRow("start") << "lukewarm:mean<=60"
                               << ""
                               << "cold, warm or hot";
        QTest::newRow("statistic") << "cold:avg<=60"
                                   << ""
                                   << "mean, median";
        QTest::newRow("no statistic") << "cold<=60"
                                      << ""
                                      << "no statistic";
        QTest::newRow("number") << "cold:mean<=sixty"
                                << ""
                                << "positive number";
        QTest::newRow("zero") << "cold:mean<=0"
                              << ""
                              << "positive number";
    }
    void limitsAreParsed() {
        QFETCH(QString, text);
        QFETCH(QString, canonical);
        QFETCH(QString, why);
        std::string reason;
        const auto l = Limit::parse(text.toStdString(), reason);
        if (canonical.isEmpty()) {
            QVERIFY(!l);
            QVERIFY2(QString::fromStdString(reason).contains(why), reason.c_str());
            QVERIFY(QString::fromStdString(reason).contains("cold:mean<=60")); // the example
        } else {
            QVERIFY2(l, reason.c_str());
            QCOMPARE(QString::fromStdString(l->text()), canonical);
        }
    }

    // Each limit against its kind's statistic; a kind without a fixed run fails.
    void limitsAreChecked() {
        std::vector<TtffRun> runs;
        for (int i = 0; i < 4; ++i)
            runs.push_back(fixedRun(ReceiverAction::ColdStart, i + 1, 50.0 + i * 10)); // 50..80
        TtffRun timeout;
        timeout.start = ReceiverAction::WarmStart;
        runs.push_back(timeout);
        std::string why;
        const std::vector<Limit> limits = {
                *Limit::parse("cold:mean<=65", why), *Limit::parse("cold:max<=70", why),
                *Limit::parse("cold:median<=65", why), *Limit::parse("warm:mean<=40", why),
                *Limit::parse("hot:mean<=10", why)};
        const auto r = checkLimits(limits, runs);
        QCOMPARE(r.size(), std::size_t(5));
        QCOMPARE(*r[0].value, 65.0);
        QVERIFY(r[0].pass); // equal is within
        QCOMPARE(*r[1].value, 80.0);
        QVERIFY(!r[1].pass);
        QCOMPARE(*r[2].value, 65.0);
        QVERIFY(r[2].pass);
        QVERIFY(!r[3].value && !r[3].pass); // no warm run fixed
        QVERIFY(!r[4].value && !r[4].pass); // no hot run at all
        std::string out;
        JsonWriter w(out);
        w.beginObject();
        writeLimitsJson(w, r);
        w.endObject();
        const QJsonArray a = QJsonDocument::fromJson(QByteArray::fromStdString(out))
                                     .object()
                                     .value("limits")
                                     .toArray();
        QCOMPARE(a.size(), 5);
        QCOMPARE(a[1].toObject().value("limit").toString(), QString("cold:max<=70"));
        QCOMPARE(a[1].toObject().value("value_s").toDouble(), 80.0);
        QCOMPARE(a[1].toObject().value("pass").toBool(), false);
        QVERIFY(a[3].toObject().value("value_s").isNull());
    }
};

QTEST_GUILESS_MAIN(TstTtffRuns)
#include "tst_ttff_runs.moc"
