// The Nemerix dialect through gnss-cli: decode (with the spec's examples, a renamed prefix and
// the lenient switch), schema nemerix, encode nemerix KEY=VALUE and --query.
#include "cli_run.h"
#include "examples_table.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

using namespace gnss::test;

namespace {

Run cli(const QStringList &args, const QByteArray &stdinData = {}) {
    return runCli(args, stdinData, 60000);
}

} // namespace

class TstNemerixCli : public QObject {
    Q_OBJECT
private slots:
    void decodeEverySpecExample();
    void decodeRenamedPrefixWithAlias();
    void schemaListsEverySetting();
    void encodeSettings();
    void encodeQuery();
    void encodeRefusesOutOfRange();
};

void TstNemerixCli::decodeEverySpecExample() {
    QByteArray input;
    int placeholders = 0, bad = 0;
    for (const auto &e : gnss::test::loadSpecExamples()) {
        if (e.vendor != "nemerix") continue;
        input += QByteArray::fromStdString(e.sentence()) + "\r\n";
        (e.verdict == "bad" ? bad : placeholders)++;
    }
    if (input.isEmpty()) QSKIP("examples.tsv not found (shared folder absent)");
    const Run strict = cli({"decode", "--dialect", "nemerix", "-"}, input);
    QCOMPARE(strict.exitCode, 0);
    const auto lines = jsonLines(strict.out);
    QCOMPARE(lines.size(), placeholders + bad);
    int decoded = 0, flagged = 0;
    for (const auto &l : lines) {
        if (l.contains("data")) ++decoded;
        if (l["checksum"].toString() == "bad") {
            ++flagged;
            QVERIFY(l["error"].toString().contains("checksum mismatch"));
        }
    }
    QCOMPARE(decoded, placeholders);
    QCOMPARE(flagged, bad);
    const Run lenient = cli({"decode", "--dialect", "nemerix", "--lenient", "-"}, input);
    for (const auto &l : jsonLines(lenient.out))
        QVERIFY2(l.contains("data"), qPrintable(l["line"].toString()));
}

void TstNemerixCli::decodeRenamedPrefixWithAlias() {
    const Run r = cli({"decode", "--dialect", "nemerix", "--alias", "PXYZW=PNMRX", "-"},
                      "$PXYZW112, 1, 5\r\n");
    QCOMPARE(r.exitCode, 0);
    const auto l = jsonLines(r.out);
    QCOMPARE(l.size(), 1);
    QCOMPARE(l[0]["data"].toObject()["off_period_s"].toInt(), 5);
}

void TstNemerixCli::schemaListsEverySetting() {
    const Run r = cli({"schema", "nemerix"});
    QCOMPARE(r.exitCode, 0);
    const auto doc = QJsonDocument::fromJson(r.out);
    QStringList keys;
    for (const auto &v : doc.array()) keys << v.toObject()["key"].toString();
    for (const char *k : {"serial.baud", "rate.GGA", "output.sequence", "datum.mapDatum",
                          "fix.timeZone", "fix.minSnr", "nav.mode", "power.mode"})
        QVERIFY2(keys.contains(k), k);
}

void TstNemerixCli::encodeSettings() {
    const Run r =
            cli({"encode", "nemerix", "fix.minSnr=35", "fix.timeZone=-2:0", "serial.baud=4800"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(QString::fromUtf8(r.out).trimmed(),
             QString("$PNMRX110,0,-2:0,4,35*7E\n$PNMRX100,0,4800,0*48"));
}

void TstNemerixCli::encodeQuery() {
    const Run r = cli({"encode", "nemerix", "--query", "fix.minSnr", "datum.mapDatum"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(QString::fromUtf8(r.out).trimmed(), QString("$PNMRX603*6C"));
}

void TstNemerixCli::encodeRefusesOutOfRange() {
    const Run r = cli({"encode", "nemerix", "fix.minSnr=50"});
    QVERIFY(r.exitCode != 0);
    QVERIFY(r.out.isEmpty());
    QVERIFY2(r.err.contains("fix.minSnr: 50 is out of range; accepted: 20..45 dB-Hz"),
             r.err.constData());
}

QTEST_APPLESS_MAIN(TstNemerixCli)
#include "tst_nemerix_cli.moc"
