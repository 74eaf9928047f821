// Where a typed time lies in a log and a --from/--to range cut to it (log_range.h): a time or
// epoch wholly outside the log is refused, a range that only reaches past an end is cut and says
// so. The log: 600 epochs at 1 Hz from 10:00:00 (#0) to 10:10:29 (#599), epochs 10:05:00-10:05:29
// missing (a gap), no receiver reset.
#include "logview/log_range.h"
#include "logview_files.h"
#include "scenario_log.h"

using namespace gnss;
using namespace gnss::logview;

namespace {
std::optional<TimeSpec> spec(const char *text) {
    if (!*text) return std::nullopt;
    return parseTimeSpec(text);
}
} // namespace

class TstLogRange : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    DialectRegistry registry_ = makeBuiltinRegistry();
    std::unique_ptr<LogView> dated_, undated_;

    std::unique_ptr<LogView> open(bool withDate, const char *name) {
        test::Scenario sc;
        sc.withDate = withDate;
        sc.resetAt = 1'000'000; // no reset: the times run forward
        const std::string path = dir_.filePath(name).toStdString();
        if (!test::writeFile(path, test::scenarioLog(sc))) return nullptr;
        auto view = std::make_unique<LogView>(registry_);
        if (!test::openAndWait(*view, path)) return nullptr;
        return view;
    }

private slots:
    void initTestCase() {
        dated_ = open(true, "dated.nmea");
        undated_ = open(false, "undated.nmea");
        QVERIFY(dated_ && undated_);
        QCOMPARE(dated_->epochCount(), std::size_t(600));
        QCOMPARE(logSpanText(*dated_),
                 std::string("2024-03-15T10:00:00.000Z (#0) to 2024-03-15T10:10:29.000Z (#599)"));
        QCOMPARE(logSpanText(*undated_), std::string("10:00:00.000 (#0) to 10:10:29.000 (#599)"));
    }

    void lookUp_data() {
        QTest::addColumn<bool>("withDate");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<int>("place");
        QTest::addColumn<int>("epoch"); // Inside: the epoch found
        const int in = int(TimePlace::Inside), before = int(TimePlace::BeforeStart),
                  after = int(TimePlace::AfterEnd), untimed = int(TimePlace::Untimed);
        QTest::newRow("first epoch") << true << "#0" << in << 0;
        QTest::newRow("last epoch") << true << "#599" << in << 599;
        QTest::newRow("epoch past the end") << true << "#3000" << after << 0;
        QTest::newRow("epoch just past the end") << true << "#600" << after << 0;
        QTest::newRow("time of the first epoch") << true << "10:00:00" << in << 0;
        QTest::newRow("within the second before") << true << "09:59:59.5" << in << 0;
        QTest::newRow("a second before the start") << true << "09:59:59" << before << 0;
        QTest::newRow("an hour before the start") << true << "9:00" << before << 0;
        QTest::newRow("in the gap: the epoch after it") << true << "10:05:10" << in << 300;
        QTest::newRow("time of the last epoch") << true << "10:10:29" << in << 599;
        QTest::newRow("after the end") << true << "10:10:30" << after << 0;
        QTest::newRow("late in the day") << true << "23:59:59" << after << 0;
        QTest::newRow("whole UTC inside") << true << "2024-03-15T10:01:00Z" << in << 60;
        QTest::newRow("whole UTC a day later") << true << "2024-03-16T10:01:00Z" << after << 0;
        QTest::newRow("whole UTC a day earlier") << true << "2024-03-14T10:01:00Z" << before << 0;
        QTest::newRow("no date: time of day") << false << "10:01:00" << in << 60;
        QTest::newRow("no date: whole UTC") << false << "2024-03-15T10:01:00Z" << untimed << 0;
        QTest::newRow("no date: epoch") << false << "#5" << in << 5;
    }
    void lookUp() {
        QFETCH(bool, withDate);
        QFETCH(QString, typed);
        QFETCH(int, place);
        QFETCH(int, epoch);
        const auto t = parseTimeSpec(typed.toStdString());
        QVERIFY(t);
        const TimeLookup at = lookUpTime(withDate ? *dated_ : *undated_, *t);
        QCOMPARE(int(at.place), place);
        if (at.place == TimePlace::Inside) QCOMPARE(int(at.epoch), epoch);
    }

    void range_data() {
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<int>("refusal");
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("last");
        QTest::addColumn<bool>("cutStart");
        QTest::addColumn<bool>("cutEnd");
        using R = EpochRange::Refusal;
        const int none = int(R::None);
        QTest::newRow("whole log") << ""
                                   << "" << none << 0 << 599 << false << false;
        QTest::newRow("ten seconds") << "10:01:00"
                                     << "10:01:09" << none << 60 << 69 << false << false;
        QTest::newRow("one epoch by number") << "#0"
                                             << "#0" << none << 0 << 0 << false << false;
        QTest::newRow("across the gap") << "10:04:58"
                                        << "10:05:31" << none << 298 << 301 << false << false;
        QTest::newRow("from before the start: cut") << "9:00"
                                                    << "" << none << 0 << 599 << true << false;
        QTest::newRow("to after the end: cut") << ""
                                               << "11:00" << none << 0 << 599 << false << true;
        QTest::newRow("to an epoch past the end: cut")
                << "#590"
                << "#3000" << none << 590 << 599 << false << true;
        QTest::newRow("both ends cut") << "09:00:00"
                                       << "12:00:00" << none << 0 << 599 << true << true;
        QTest::newRow("to the last epoch: not cut")
                << ""
                << "10:10:29" << none << 0 << 599 << false << false;
        QTest::newRow("from an epoch past the end")
                << "#3000"
                << "" << int(R::FromAfterEnd) << 0 << 0 << false << false;
        QTest::newRow("from after the end")
                << "10:10:30"
                << "" << int(R::FromAfterEnd) << 0 << 0 << false << false;
        QTest::newRow("to before the start")
                << ""
                << "09:59:00" << int(R::ToBeforeStart) << 0 << 0 << false << false;
        QTest::newRow("from after to") << "#10"
                                       << "#5" << int(R::Empty) << 0 << 0 << false << false;
        QTest::newRow("from after to, times")
                << "10:02:00"
                << "10:01:00" << int(R::Empty) << 0 << 0 << false << false;
    }
    void range() {
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(int, refusal);
        QFETCH(int, first);
        QFETCH(int, last);
        QFETCH(bool, cutStart);
        QFETCH(bool, cutEnd);
        const EpochRange r = resolveRange(*dated_, spec(from.toLatin1().constData()),
                                          spec(to.toLatin1().constData()));
        QCOMPARE(int(r.refusal), refusal);
        if (r.refusal != EpochRange::Refusal::None) return;
        QCOMPARE(int(r.first), first);
        QCOMPARE(int(r.last), last);
        QCOMPARE(r.cutStart, cutStart);
        QCOMPARE(r.cutEnd, cutEnd);
    }

    void aLogWithoutDatesRefusesWholeTimes() {
        const auto utc = parseTimeSpec("2024-03-15T10:00:00Z");
        QCOMPARE(int(resolveRange(*undated_, utc, std::nullopt).refusal),
                 int(EpochRange::Refusal::Untimed));
        QCOMPARE(int(resolveRange(*undated_, std::nullopt, utc).refusal),
                 int(EpochRange::Refusal::Untimed));
        const EpochRange r =
                resolveRange(*undated_, parseTimeSpec("10:01:00"), parseTimeSpec("10:01:09"));
        QCOMPARE(int(r.refusal), int(EpochRange::Refusal::None));
        QCOMPARE(int(r.first), 60);
        QCOMPARE(int(r.last), 69);
    }
};

QTEST_GUILESS_MAIN(TstLogRange)
#include "tst_log_range.moc"
