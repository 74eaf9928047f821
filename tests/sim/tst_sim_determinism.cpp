// Every simulated receiver is deterministic for a seed (same seed, same bytes; another seed,
// another sky noise), and its output is limited to what its line speed carries.
#include "builtin/simulators.h"
#include "builtin_registry.h"
#include "sim_output.h"

#include "builtin/dialects.h"
#include "core/sentence_builder.h"

#include <QTest>

using namespace gnss;
using namespace gnss::sim;

using gnss::test::builtinRegistry;

namespace {

std::string run(std::string_view dialect, std::uint32_t seed, int baud = 0) {
    SimOptions o;
    o.seed = seed;
    o.baud = baud;
    auto rx = makeReceiver(dialect, o);
    std::string out;
    for (int i = 0; i < 40; ++i) {
        rx->advance(0.5);
        out += rx->takeOutput();
    }
    return out;
}

// A row for each dialect the registry can simulate, in a column "dialect".
void dialectRows() {
    QTest::addColumn<QString>("dialect");
    for (std::string_view d : builtinSimulators().dialects())
        QTest::newRow(std::string(d).c_str()) << QString::fromUtf8(d.data(), d.size());
}

} // namespace

class TstSimDeterminism : public QObject {
    Q_OBJECT
private slots:
    void sameSeedSameBytes_data() { dialectRows(); }
    void sameSeedSameBytes() {
        QFETCH(QString, dialect);
        const std::string d = dialect.toStdString();
        const std::string a = run(d, 42), b = run(d, 42), c = run(d, 43);
        QVERIFY(a.size() > 1000);
        QVERIFY(a == b);
        QVERIFY(a != c);
        const auto s = gnss::test::summarize(a, d);
        QCOMPARE(s.checksumErrors, 0);
        QCOMPARE(s.decodeErrors, 0);
    }
    void outputIsLimitedByTheLineSpeed_data() { dialectRows(); }
    void outputIsLimitedByTheLineSpeed() {
        QFETCH(QString, dialect);
        SimOptions o;
        o.baud = 1200; // 120 bytes a second: far less than any default output
        auto rx = makeReceiver(dialect.toStdString(), o);
        rx->advance(60.0);
        const std::string out = rx->takeOutput();
        // At most the 4 KB buffer plus 120 bytes a second, whole sentences only.
        QVERIFY2(out.size() <= 4096 + 60 * 120 + 200, QByteArray::number(qulonglong(out.size())));
        QVERIFY(rx->droppedSentences() > 0);
        const auto s = gnss::test::summarize(out, dialect.toStdString());
        QCOMPARE(s.checksumErrors, 0);
        QVERIFY(!s.lines.empty());
    }
};

QTEST_APPLESS_MAIN(TstSimDeterminism)
#include "tst_sim_determinism.moc"
