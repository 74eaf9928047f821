// Simulated restarts: the --ttff grammar (or the reason it is refused), draws that follow the
// distribution asked for, and every family taking its own restart commands (from its dialect
// record's actions) to a first fix after the time its model gives: the built-in one, the VT002's
// datasheet averages, or one set on purpose. Simulated time throughout: no waiting.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "core/sentence_builder.h"
#include "sim/receiver.h"
#include "sim/ttff_model.h"

#include "core/framer.h"
#include "core/sentence.h"

#include <QTest>

#include <cmath>

using namespace gnss;
using namespace gnss::sim;

namespace {

// Whether `out` holds a GGA with a fix (quality field > 0).
bool hasFix(const std::string &out) {
    bool fix = false;
    Framer f;
    f.feed(out, [&](std::string_view line) {
        Sentence s;
        if (!s.parse(line) || s.address().size() < 5 || s.address().substr(2) != "GGA") return;
        const std::string_view q = s.field(5);
        if (!q.empty() && q != "0") fix = true;
    });
    return fix;
}

// Seconds from `command` to the first epoch with a fix, in steps of 0.1 s (NaN: none in `limit`).
double timeToFix(Receiver &rx, const std::string &command, double limit) {
    rx.takeOutput();
    rx.receive(command);
    rx.advance(0.25); // the command is carried out; the fix is lost
    rx.takeOutput();
    for (double t = 0.25; t < limit; t += 0.1) {
        rx.advance(0.1);
        if (hasFix(rx.takeOutput())) return t + 0.1;
    }
    return NAN;
}

std::string commandFor(std::string_view dialect, ReceiverAction action) {
    static const DialectRegistry registry = makeBuiltinRegistry();
    const Dialect *d = registry.find(dialect);
    for (const ActionDef &a : d->actions)
        if (a.action == action) return buildSentence(a.body) + "\r\n";
    return {};
}

} // namespace

class TstSimTtff : public QObject {
    Q_OBJECT
private slots:
    void specsParse_data() {
        QTest::addColumn<QString>("spec");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("all kinds") << "cold=60:8,warm=38:5,hot=12:2,power=3" << true << "";
        QTest::newRow("mean alone") << "cold=45" << true << "";
        QTest::newRow("unknown kind") << "lukewarm=5" << false << "KIND";
        QTest::newRow("no value") << "cold" << false << "KIND";
        QTest::newRow("negative") << "hot=-1" << false << "hot";
        QTest::newRow("spread past the mean") << "warm=10:20" << false << "spread";
        QTest::newRow("not a number") << "cold=slow" << false << "cold";
        QTest::newRow("empty") << "" << false << "KIND";
    }
    void specsParse() {
        QFETCH(QString, spec);
        QFETCH(bool, ok);
        QFETCH(QString, mentions);
        std::string why;
        const auto m = TtffModel::parse(spec.toStdString(), why);
        QCOMPARE(m.has_value(), ok);
        if (!ok) QVERIFY2(QString::fromStdString(why).contains(mentions), why.c_str());
    }

    // Two thousand cold starts of 60 ± 9 s: their mean and spread are what was asked; none
    // outside [20, 180].
    void drawsFollowTheDistribution() {
        std::string why;
        const TtffModel m = *TtffModel::parse("cold=60:9", why);
        std::mt19937 rng(7);
        double sum = 0, sq = 0, lo = 1e9, hi = 0;
        const int n = 2000;
        for (int i = 0; i < n; ++i) {
            const double t = m.draw(ResetKind::Cold, rng);
            sum += t;
            sq += t * t;
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        const double mean = sum / n, sd = std::sqrt(sq / n - mean * mean);
        QVERIFY2(std::abs(mean - 60) < 1.0, QByteArray::number(mean));
        QVERIFY2(std::abs(sd - 9) < 1.0, QByteArray::number(sd));
        QVERIFY(lo >= 20 && hi <= 180);
        // Kinds not set keep the base's.
        const TtffModel merged = m.over(TtffModel::builtin());
        QCOMPARE(merged.of(ResetKind::Hot).mean, 2.0);
        QCOMPARE(merged.of(ResetKind::Cold).mean, 60.0);
    }

    // Each family's restart commands, as its dialect record has them, with times set on purpose:
    // the fix comes back after that time (an epoch's worth of slack), and each kind its own.
    void eachFamilyRestartsAsToldByItsCommands_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<int>("action");
        QTest::addColumn<double>("seconds");
        const struct {
            const char *dialect;
            ReceiverAction action;
            double seconds;
        } rows[] = {{"nvs", ReceiverAction::ColdStart, 30},
                    {"nvs", ReceiverAction::WarmStart, 20},
                    {"geostar", ReceiverAction::ColdStart, 30},
                    {"geostar", ReceiverAction::WarmStart, 20},
                    {"geostar", ReceiverAction::HotStart, 10},
                    {"nemerix", ReceiverAction::ColdStart, 30},
                    {"nemerix", ReceiverAction::WarmStart, 20},
                    {"nemerix", ReceiverAction::HotStart, 10}};
        for (const auto &r : rows)
            QTest::addRow("%s %s", r.dialect, std::string(toString(r.action)).c_str())
                    << r.dialect << int(r.action) << r.seconds;
    }
    void eachFamilyRestartsAsToldByItsCommands() {
        QFETCH(QString, dialect);
        QFETCH(int, action);
        QFETCH(double, seconds);
        const std::string command =
                commandFor(dialect.toStdString(), static_cast<ReceiverAction>(action));
        QVERIFY2(!command.empty(), "the dialect has no such restart");
        SimOptions o;
        std::string why;
        o.ttff = *TtffModel::parse("cold=30,warm=20,hot=10", why);
        auto rx = builtinSimulators().make(dialect.toStdString(), o);
        rx->advance(10); // fixed since power-on (3 s)
        QVERIFY(hasFix(rx->takeOutput()));
        const double t = timeToFix(*rx, command, 90);
        QVERIFY2(t >= seconds && t <= seconds + 1.5,
                 qPrintable(QString("%1 s after %2").arg(t).arg(QString::fromStdString(command))));
    }

    // The VT002 by default takes its datasheet's averages: over twenty starts of each kind the
    // medians come within 10 % of 12, 38 and 60 s.
    void theVt002KeepsItsDatasheet() {
        const struct {
            ReceiverAction action;
            double mean;
        } kinds[] = {{ReceiverAction::HotStart, 12},
                     {ReceiverAction::WarmStart, 38},
                     {ReceiverAction::ColdStart, 60}};
        for (const auto &k : kinds) {
            SimOptions o;
            o.seed = 11;
            auto rx = builtinSimulators().make("nemerix", o);
            rx->advance(10);
            std::vector<double> times;
            for (int run = 0; run < 20; ++run) {
                const double t = timeToFix(*rx, commandFor("nemerix", k.action), 200);
                QVERIFY(!std::isnan(t));
                times.push_back(t);
                rx->advance(5); // holds the fix a while
            }
            std::sort(times.begin(), times.end());
            const double median = (times[9] + times[10]) / 2;
            QVERIFY2(std::abs(median - k.mean) <= 0.1 * k.mean,
                     qPrintable(QString("%1: median %2 s").arg(k.mean).arg(median)));
            QVERIFY(times.front() < times.back()); // a spread, not one number
        }
    }
};

QTEST_GUILESS_MAIN(TstSimTtff)
#include "tst_sim_ttff.moc"
