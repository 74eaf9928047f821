// The plan of an apply (protocol/config/apply_plan.h), without a queue, on the built-in dialect
// records: the settings one command writes together, the order commands go in, and the speed
// the host's side of the line follows to.
#include "builtin_registry.h"
#include "config/apply_plan.h"

#include <QTest>

using namespace gnss;
using namespace gnss::config;

namespace {

const Dialect &dialect(const char *id) {
    const Dialect *d = test::builtinRegistry().find(id);
    if (!d) qFatal("no dialect %s", id);
    return *d;
}

QStringList keysOf(const std::vector<KeyValue> &values) {
    QStringList out;
    for (const auto &kv : values) out << QString::fromStdString(kv.key + "=" + kv.value);
    return out;
}

} // namespace

class TstApplyPlan : public QObject {
    Q_OBJECT
private slots:
    // PNVGRZA,N sets a port's baud and protocol together: changing one sends the other with its
    // value in force, or its default when none is known.
    void aPortsSettingsGoTogether() {
        const Dialect &nvs = dialect("nvs");
        std::vector<KeyValue> companions;
        auto none = [](std::string_view) { return std::optional<std::string>(); };
        auto plan = withCompanions(nvs, {{"port.COM2.baud", "38400"}}, none, &companions);
        QCOMPARE(keysOf(plan), QStringList({"port.COM2.baud=38400", "port.COM2.protocol=1"}));
        QCOMPARE(keysOf(companions), QStringList({"port.COM2.protocol=1"}));

        auto rtcm = [](std::string_view key) {
            return key == "port.COM2.protocol" ? std::optional<std::string>("7") : std::nullopt;
        };
        plan = withCompanions(nvs, {{"port.COM2.baud", "38400"}}, rtcm);
        QCOMPARE(keysOf(plan), QStringList({"port.COM2.baud=38400", "port.COM2.protocol=7"}));

        // Both given: nothing added; another port's settings are not touched.
        companions.clear();
        plan = withCompanions(nvs, {{"port.COM2.protocol", "7"}, {"port.COM2.baud", "9600"}}, none,
                              &companions);
        QCOMPARE(keysOf(plan), QStringList({"port.COM2.protocol=7", "port.COM2.baud=9600"}));
        QVERIFY(companions.empty());
        // A setting of a command of its own brings nothing along.
        QCOMPARE(keysOf(withCompanions(nvs, {{"rtk.ELGPS", "5"}}, none)),
                 QStringList({"rtk.ELGPS=5"}));
    }

    // Restarts, then other ports' speeds, then the host's own port, then protocol changes; the
    // rest first, in the order given.
    void commandsThatChangeTheLinkGoLast() {
        const Dialect &nvs = dialect("nvs");
        std::vector<std::string> sentences{"$PNVGRZA,1,38400,1", "$PNVGRTK,ELGPS,5",
                                           "$PNVGRZA,2,9600,7", "$PNVGRST,W", "$PNVGRTK,ELGLO,5"};
        QCOMPARE(effectRank(nvs, "$PNVGRTK,ELGPS,5"), 0);
        QCOMPARE(effectRank(nvs, "$PNVGRST,W"), 1);
        QCOMPARE(effectRank(nvs, "$PNVGRZA,2,9600,7"), 2);
        QCOMPARE(effectRank(nvs, "$PNVGRZA,1,38400,1"), 3);
        QCOMPARE(effectRank(nvs, "not a sentence"), 0);
        orderForSending(nvs, sentences);
        QCOMPARE(sentences,
                 (std::vector<std::string>{"$PNVGRTK,ELGPS,5", "$PNVGRTK,ELGLO,5", "$PNVGRST,W",
                                           "$PNVGRZA,2,9600,7", "$PNVGRZA,1,38400,1"}));
    }

    void theLineFollowsTheHostsPortOnly() {
        const Dialect &nvs = dialect("nvs");
        const std::vector<KeyValue> applying{{"port.COM1.baud", "38400"},
                                             {"port.COM2.baud", "9600"}};
        // The host's port (COM1): the line follows to the speed set.
        QCOMPARE(lineBaudAfter(nvs, "$PNVGRZA,1,38400,1", 115200, applying), 38400);
        // Another port: the line stays.
        QCOMPARE(lineBaudAfter(nvs, "$PNVGRZA,2,9600,1", 115200, applying), 115200);
        // Not a speed command, or the line's rate unknown: nothing to follow.
        QVERIFY(!lineBaudAfter(nvs, "$PNVGRTK,ELGPS,5", 115200, applying));
        QVERIFY(!lineBaudAfter(nvs, "$PNVGRZA,1,38400,1", 0, applying));
        // The host's port without its speed among the changes: not known.
        QVERIFY(!lineBaudAfter(nvs, "$PNVGRZA,1,38400,1", 115200, {}));
    }
};

QTEST_GUILESS_MAIN(TstApplyPlan)
#include "tst_apply_plan.moc"
