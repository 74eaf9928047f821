// The NVS reply rules classify the spec's replies: which sentence answers each command, success
// versus refusal, multi-sentence answers (PNVGIDL SHOW), commands without a reply.
#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "nvs/nvs_dialect.h"

#include <QTest>

using namespace gnss;

namespace {

// The rule the command queue uses: first row whose address matches and whose first field
// matches (an empty first field covers every command with that address).
const ReplyRule *ruleFor(const Sentence &command) {
    for (const auto &r : nvs::dialect().replyRules)
        if (r.commandAddress == command.address() &&
            (r.firstField.empty() || r.firstField == command.field(0)))
            return &r;
    return nullptr;
}

// Accepts a sentence with or without checksum ("$PNVGVER,NVS,..." gets one computed).
std::string complete(const QString &text) {
    std::string err;
    return completeSentence(text.toStdString(), err);
}

} // namespace

Q_DECLARE_METATYPE(gnss::ReplyVerdict)

class TstNvsReplyRules : public QObject {
    Q_OBJECT
private slots:
    void replyRulesClassifyTheSpecReplies_data();
    void replyRulesClassifyTheSpecReplies();
    void idlShowAnswersWithCountItems();
    void commandsWithoutReplyAndTheirEffects();
    void everyCommandNameHasAReplyRule();
};

void TstNvsReplyRules::replyRulesClassifyTheSpecReplies_data() {
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("reply");
    QTest::addColumn<ReplyVerdict>("verdict");
    using V = ReplyVerdict;
    QTest::newRow("VER reply") << "$PNVGVER*4E"
                               << "$PNVGVER,NVS,RTA,0029,CSM24,0205" << V::Accepted;
    QTest::newRow("VER ignores GGA") << "$PNVGVER*4E"
                                     << "$GPGGA,120000,,,,,0,00,,,M,,M,," << V::NotMine;
    QTest::newRow("Q TST answered") << "$GPGPQ,PNVGTST*21"
                                    << "$PNVGTST,ID,1234,ANT,0" << V::Accepted;
    QTest::newRow("Q GGA answered by GNGGA") << "$GPGPQ,GGA"
                                             << "$GNGGA,120000,,,,,0,00,,,M,,M,," << V::Accepted;
    QTest::newRow("Q TST ignores BSS") << "$GPGPQ,PNVGTST*21"
                                       << "$PNVGBSS,1,0,1,0.5,1.0" << V::NotMine;
    QTest::newRow("RZA spec reply") << "$PNVGRZA,1,115200,1"
                                    << "$PNVGRZA,1,115200,1*6D" << V::Accepted;
    QTest::newRow("RZA current port") << "$PNVGRZA,0,115200,1"
                                      << "$PNVGRZA,1,115200,1*6D" << V::Accepted;
    QTest::newRow("RZA other speed") << "$PNVGRZA,1,460800,1"
                                     << "$PNVGRZA,1,115200,1*6D" << V::Refused;
    QTest::newRow("NME echo") << "$PNVGNME,2,7,0"
                              << "$PNVGNME,2,7,0" << V::Accepted;
    QTest::newRow("PPS spec reply") << "$PNVGPPS,P,S,U,1,1000,D,0"
                                    << "$PNVGPPS,P,S,U,1,1000,D,0*62" << V::Accepted;
    QTest::newRow("PPS read back") << "$PNVGPPS,,,,,,,"
                                   << "$PNVGPPS,P,S,U,1,1000,D,0*62" << V::Accepted;
    QTest::newRow("CFG W confirmed") << "$PNVGCFG,W"
                                     << "$PNVGCFG,W" << V::Accepted;
    QTest::newRow("RTK base spec reply")
            << "$PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737"
            << "$PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737*1D" << V::Accepted;
    QTest::newRow("RTK BLH spec reply")
            << "$PNVGRTK,BASEBLH,0.8263954319,0.1674465031,467.7040"
            << "$PNVGRTK,BASEBLH,0.8263954319,0.1674465031,467.7040*04" << V::Accepted;
    QTest::newRow("RTK query spec reply")
            << "$PNVGRTK,BASEXYZ"
            << "$PNVGRTK,BASEXYZ,4268995.2112,721584.9731,4668481.3737*2F" << V::Accepted;
    QTest::newRow("RTK value not taken") << "$PNVGRTK,MODE,4"
                                         << "$PNVGRTK,MODE,2" << V::Refused;
    QTest::newRow("RTK parameter missing") << "$PNVGRTK,MODE,PVTRATE"
                                           << "$PNVGRTK,MODE,2" << V::Refused;
    QTest::newRow("RTK other request's reply") << "$PNVGRTK,SNR"
                                               << "$PNVGRTK,MODE,2" << V::NotMine;
    QTest::newRow("IDL MODE spec reply") << "$PNVGIDL,MODE,1"
                                         << "$PNVGIDL,MODE,1*7C" << V::Accepted;
    QTest::newRow("IDL ADD spec reply") << "$PNVGIDL,ADD,0003,0.0720"
                                        << "$PNVGIDL,ADD,0003,0.0720*3B" << V::Accepted;
    QTest::newRow("IDL REMOVE spec reply") << "$PNVGIDL,REMOVE,0032"
                                           << "$PNVGIDL,REMOVE,OK*4C" << V::Accepted;
    QTest::newRow("IDL REMOVE refused") << "$PNVGIDL,REMOVE,0032"
                                        << "$PNVGIDL,REMOVE,ERROR" << V::Refused;
    QTest::newRow("IDL CLEAR spec reply") << "$PNVGIDL,CLEAR"
                                          << "$PNVGIDL,CLEAR,OK*13" << V::Accepted;
    QTest::newRow("IDL CLEAR ignores MODE") << "$PNVGIDL,CLEAR"
                                            << "$PNVGIDL,MODE,1*7C" << V::NotMine;
}

void TstNvsReplyRules::replyRulesClassifyTheSpecReplies() {
    QFETCH(QString, command);
    QFETCH(QString, reply);
    QFETCH(ReplyVerdict, verdict);
    const std::string cmdLine = complete(command), replyLine = complete(reply);
    Sentence c, r;
    QVERIFY(c.parse(cmdLine));
    QVERIFY(r.parse(replyLine));
    QCOMPARE(int(r.checksum()), int(ChecksumStatus::Ok));
    const ReplyRule *rule = ruleFor(c);
    QVERIFY(rule);
    QVERIFY(rule->classify);
    ReplyProgress progress;
    QCOMPARE(int(rule->classify(c, r, progress)), int(verdict));
}

void TstNvsReplyRules::idlShowAnswersWithCountItems() {
    Sentence c;
    const std::string cmdLine = complete("$PNVGIDL,SHOW");
    QVERIFY(c.parse(cmdLine));
    const ReplyRule *rule = ruleFor(c);
    QVERIFY(rule && rule->classify);
    QCOMPARE(rule->firstField, std::string_view("SHOW"));
    const char *items[] = {"$PNVGIDL,4,1,0001,0.0000*54", "$PNVGIDL,4,2,0002,0.0020*56",
                           "$PNVGIDL,4,3,0032,0.0000*56", "$PNVGIDL,4,4,0043,0.0720*52"};
    ReplyProgress progress;
    for (int i = 0; i < 4; ++i) {
        Sentence r;
        QVERIFY(r.parse(items[i]));
        QCOMPARE(int(r.checksum()), int(ChecksumStatus::Ok));
        const auto v = rule->classify(c, r, progress);
        QCOMPARE(int(v), int(i < 3 ? ReplyVerdict::Partial : ReplyVerdict::Accepted));
    }
    QCOMPARE(progress.expected, 4);
    QCOMPARE(progress.received, 4);
}

void TstNvsReplyRules::commandsWithoutReplyAndTheirEffects() {
    struct Row {
        const char *command;
        bool hasReply;
        CommandEffect effect;
    } rows[] = {
            {"$PNVGRST,F", false, CommandEffect::ResetsReceiver},
            {"$PNVGRZB,PORT,1,RMC,1", false, CommandEffect::ChangesOutput},
            {"$PNVGRZA,1,115200,1", true, CommandEffect::ChangesBaud},
            {"$PNVGCFG,R", true, CommandEffect::ResetsReceiver},
            {"$PNVGCFG,W", true, CommandEffect::None},
    };
    for (const auto &row : rows) {
        const std::string line = complete(row.command);
        Sentence c;
        QVERIFY(c.parse(line));
        const ReplyRule *rule = ruleFor(c);
        QVERIFY2(rule, row.command);
        QCOMPARE(rule->classify != nullptr, row.hasReply);
        QCOMPARE(int(rule->effect), int(row.effect));
        QVERIFY(rule->timeoutMs > 0);
        QVERIFY(!rule->description.empty());
    }
}

void TstNvsReplyRules::everyCommandNameHasAReplyRule() {
    for (auto name : nvs::dialect().commandNames) {
        bool found = false;
        for (const auto &r : nvs::dialect().replyRules) found = found || r.commandAddress == name;
        QVERIFY2(found, std::string(name).c_str());
    }
}

QTEST_APPLESS_MAIN(TstNvsReplyRules)
#include "tst_nvs_reply_rules.moc"
