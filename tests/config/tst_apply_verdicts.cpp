// The verdict rule of an apply (protocol/config/apply_verdicts.h), without a queue: each row is
// what is known of one setting when its apply ends, and the verdict it gets; then the verdicts
// of an interrupted apply once its settings are read back; then the fate of a command from the
// outcomes of its sentences. The settings are the NV08C-RTK's: rtk.ELGPS is read back,
// port.COM2.baud is write-only (PNVGRZA answers only when set).
#include "builtin_registry.h"
#include "config/apply_verdicts.h"

#include <QTest>

using namespace gnss;
using namespace gnss::config;

Q_DECLARE_METATYPE(gnss::config::Verdict)
Q_DECLARE_METATYPE(gnss::config::CommandFate)

namespace {

const SettingDef &setting(const char *key) {
    const Dialect *nvs = test::builtinRegistry().find("nvs");
    const SettingDef *def = nvs ? findSetting(nvs->settings, key) : nullptr;
    if (!def) qFatal("no setting %s", key);
    return *def;
}

link::CommandResult result(const char *sentence, link::CommandOutcome outcome, int attempts) {
    link::CommandResult r;
    r.sentence = QString::fromLatin1(sentence);
    r.outcome = outcome;
    r.attempts = attempts;
    return r;
}

} // namespace

class TstApplyVerdicts : public QObject {
    Q_OBJECT
private slots:
    void judgeEachSetting_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("reported"); // "-": nothing reported
        QTest::addColumn<CommandFate>("fate");
        QTest::addColumn<bool>("linkLost");
        QTest::addColumn<bool>("readBackRan");
        QTest::addColumn<Verdict>("verdict");
        QTest::addColumn<QString>("shown"); // the reported value the check carries
        const QString elgps = "rtk.ELGPS", baud = "port.COM2.baud";
        using F = CommandFate;
        using V = Verdict;
        // The link stayed: what the receiver reports decides.
        QTest::newRow("read back as set")
                << elgps << "5" << F::Taken << false << true << V::Verified << "5";
        QTest::newRow("read back as set, other spelling")
                << elgps << "05" << F::Taken << false << true << V::Verified << "05";
        QTest::newRow("read back otherwise")
                << elgps << "10" << F::Taken << false << true << V::NotTaken << "10";
        QTest::newRow("not reported")
                << elgps << "-" << F::Taken << false << true << V::NotReported << "";
        QTest::newRow("its command failed")
                << elgps << "-" << F::NotSent << false << true << V::NotSent << "";
        QTest::newRow("failed, yet read back as set")
                << elgps << "5" << F::NotSent << false << true << V::Verified << "5";
        QTest::newRow("write-only, sent")
                << baud << "-" << F::Taken << false << false << V::WrittenUnverified << "";
        // Confirmed by the command's answer: never called read back (it cannot be).
        QTest::newRow("write-only, echoed as set")
                << baud << "115200" << F::Taken << false << false << V::Echoed << "115200";
        QTest::newRow("write-only, echoed otherwise")
                << baud << "9600" << F::Taken << false << false << V::NotTaken << "9600";
        QTest::newRow("write-only, failed")
                << baud << "-" << F::NotSent << false << false << V::NotSent << "";
        // The link went: only a read-back verifies a readable setting.
        QTest::newRow("lost, read back before")
                << elgps << "5" << F::Taken << true << true << V::Verified << "5";
        QTest::newRow("lost, old value before the read-back")
                << elgps << "10" << F::Taken << true << false << V::NotReadBack << "";
        QTest::newRow("lost after the answer")
                << elgps << "-" << F::Taken << true << false << V::NotReadBack << "";
        QTest::newRow("lost before the answer")
                << elgps << "-" << F::Unconfirmed << true << false << V::Unconfirmed << "";
        QTest::newRow("lost before sending")
                << elgps << "-" << F::NotSent << true << false << V::NotSent << "";
        QTest::newRow("lost, write-only echoed")
                << baud << "115200" << F::Taken << true << false << V::Echoed << "115200";
        QTest::newRow("lost, write-only taken")
                << baud << "-" << F::Taken << true << false << V::WrittenUnverified << "";
        QTest::newRow("lost, write-only unconfirmed")
                << baud << "-" << F::Unconfirmed << true << false << V::Unconfirmed << "";
        QTest::newRow("lost, write-only not sent")
                << baud << "-" << F::NotSent << true << false << V::NotSent << "";
    }

    void judgeEachSetting() {
        QFETCH(QString, key);
        QFETCH(QString, reported);
        QFETCH(CommandFate, fate);
        QFETCH(bool, linkLost);
        QFETCH(bool, readBackRan);
        QFETCH(Verdict, verdict);
        QFETCH(QString, shown);
        const SettingDef &def = setting(qPrintable(key));
        const std::string wanted = key == "rtk.ELGPS" ? "5" : "115200";
        SettingFacts facts;
        if (reported != "-") facts.reported = reported.toStdString();
        facts.fate = fate;
        facts.linkLost = linkLost;
        facts.readBackRan = readBackRan;
        const SettingCheck c = judge(def, wanted, facts);
        QCOMPARE(QString::fromStdString(c.key), key);
        QCOMPARE(QString::fromStdString(c.wanted), QString::fromStdString(wanted));
        QCOMPARE(c.verdict, verdict);
        QCOMPARE(QString::fromStdString(c.reported), shown);
    }

    void judgeAfterTheLinkReturns_data() {
        QTest::addColumn<Verdict>("before");
        QTest::addColumn<QString>("reported"); // "-": nothing reported
        QTest::addColumn<bool>("linkLost");
        QTest::addColumn<Verdict>("after");
        using V = Verdict;
        QTest::newRow("taken, read back as set") << V::NotReadBack << "5" << false << V::Verified;
        QTest::newRow("unconfirmed, read back as set")
                << V::Unconfirmed << "5" << false << V::Verified;
        QTest::newRow("unconfirmed, read back otherwise")
                << V::Unconfirmed << "10" << false << V::NotTaken;
        QTest::newRow("not sent, still the old value") << V::NotSent << "10" << false << V::NotSent;
        QTest::newRow("not sent, yet as set") << V::NotSent << "5" << false << V::Verified;
        QTest::newRow("not reported") << V::NotReadBack << "-" << false << V::NotReported;
        QTest::newRow("lost again") << V::NotReadBack << "-" << true << V::NotReadBack;
        QTest::newRow("not sent, not reported") << V::NotSent << "-" << false << V::NotSent;
    }

    void judgeAfterTheLinkReturns() {
        QFETCH(Verdict, before);
        QFETCH(QString, reported);
        QFETCH(bool, linkLost);
        QFETCH(Verdict, after);
        const SettingCheck earlier{"rtk.ELGPS", "5", {}, before};
        std::optional<std::string> r;
        if (reported != "-") r = reported.toStdString();
        const SettingCheck c = judgeReadBack(setting("rtk.ELGPS"), earlier, r, linkLost);
        QCOMPARE(c.verdict, after);
        QCOMPARE(QString::fromStdString(c.reported), reported == "-" ? QString() : reported);
    }

    void aWriteOnlySettingIsNotReadBack() {
        const SettingCheck earlier{"port.COM2.baud", "115200", {}, Verdict::WrittenUnverified};
        const SettingCheck c =
                judgeReadBack(setting("port.COM2.baud"), earlier, std::string("9600"), false);
        QCOMPARE(c.verdict, Verdict::WrittenUnverified);
        QVERIFY(c.reported.empty());
    }

    void theFateOfACommand_data() {
        using O = link::CommandOutcome;
        QTest::addColumn<QList<link::CommandResult>>("commands");
        QTest::addColumn<CommandFate>("fate");
        const char *a = "$PNVGRTK,ELGPS,5*3A";
        const char *other = "$PNVGRTK,ELGLO,5*3A";
        QTest::newRow("accepted") << QList{result(a, O::Accepted, 1)} << CommandFate::Taken;
        QTest::newRow("sent, no answer expected")
                << QList{result(a, O::Sent, 1)} << CommandFate::Taken;
        QTest::newRow("refused") << QList{result(a, O::Refused, 1)} << CommandFate::NotSent;
        QTest::newRow("timed out") << QList{result(a, O::TimedOut, 3)} << CommandFate::NotSent;
        QTest::newRow("lost in flight")
                << QList{result(a, O::LinkLost, 1)} << CommandFate::Unconfirmed;
        QTest::newRow("lost before sending")
                << QList{result(a, O::LinkLost, 0)} << CommandFate::NotSent;
        QTest::newRow("never queued")
                << QList{result(other, O::Accepted, 1)} << CommandFate::NotSent;
    }

    void theFateOfACommand() {
        QFETCH(QList<link::CommandResult>, commands);
        QFETCH(CommandFate, fate);
        QCOMPARE(fateOf({"PNVGRTK,ELGPS,5"}, commands), fate);
    }

    void aCommandOfSeveralSentences() {
        using O = link::CommandOutcome;
        const std::vector<std::string> both{"PNVGRTK,ELGPS,5", "PNVGRTK,ELGLO,5"};
        const QList<link::CommandResult> oneTakenOneLost{
                result("$PNVGRTK,ELGPS,5*3A", O::Accepted, 1),
                result("$PNVGRTK,ELGLO,5*3A", O::LinkLost, 0)};
        // One went, the other did not: the receiver may have half of it.
        QCOMPARE(fateOf(both, oneTakenOneLost), CommandFate::Unconfirmed);
        QVERIFY(anyLinkLost(oneTakenOneLost));
        QVERIFY(succeeded(oneTakenOneLost.front()));
        QVERIFY(!succeeded(oneTakenOneLost.back()));
        QCOMPARE(fateOf({}, oneTakenOneLost), CommandFate::NotSent);
    }
};

QTEST_GUILESS_MAIN(TstApplyVerdicts)
#include "tst_apply_verdicts.moc"
