// Settings profiles read from JSON (config::profileFromJson, what loadProfile reads from a file):
// keys as users write them, and nothing dropped on the way; a profile that cannot be applied
// (malformed, another dialect or model) refused whole, saying why; values a command would not
// take named before they are sent.
#include "builtin/dialects.h"
#include "config/settings_profile.h"

#include <QTest>

#include <iterator>

using namespace gnss;
using namespace gnss::config;

namespace {

QByteArray nvsProfile(const QByteArray &values) {
    return R"({"format":"gnss-workbench-settings","version":1,"dialect":"nvs","values":{)" +
           values + "}}";
}

// A profile's dialect and model against an NVS receiver's model, and the refusal's start.
struct ModelRow {
    const char *name, *dialect, *profileModel, *receiverModel, *why;
};
constexpr ModelRow kModelRows[] = {
        {"the same model", "nvs", "NV08C-RTK", "NV08C-RTK", ""},
        {"another model", "nvs", "NV08C-CSM", "NV08C-RTK",
         "the profile is for the NV08C-CSM, the receiver is a NV08C-RTK"},
        {"a profile without a model", "nvs", "", "NV08C-RTK", ""},
        {"a receiver not identified", "nvs", "NV08C-CSM", "", ""},
        // Saved when the workbench called the NV08C-RTK-A "NV08C-RTA".
        {"the model's former name", "nvs", "NV08C-RTA", "NV08C-RTK-A", ""},
        {"another model's former name", "nvs", "NV08C-RTA", "NV08C-RTK",
         "the profile is for the NV08C-RTA, the receiver is a NV08C-RTK"},
        {"another dialect", "geostar", "NV08C-RTK", "NV08C-RTK",
         "the profile is for dialect 'geostar', the receiver speaks 'nvs'"},
};

} // namespace

class TstSettingsProfile : public QObject {
    Q_OBJECT
private slots:
    // Each is refused before anything could be sent: the error names what is wrong.
    void aProfileThatCannotBeAppliedIsRefusedSayingWhy_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("why");
        QTest::newRow("not JSON") << QByteArray("rtk.ELGPS=12\n") << "not a settings profile";
        QTest::newRow("cut short")
                << nvsProfile(R"("rtk.ELGPS":"12")").left(60) << "not a settings profile";
        QTest::newRow("an array") << QByteArray("[1,2]") << "not a settings profile";
        QTest::newRow("another program's JSON")
                << QByteArray(R"({"name":"x","values":{}})") << "format is '', expected";
        QTest::newRow("a newer version")
                << QByteArray(R"({"format":"gnss-workbench-settings","version":2,"dialect":"nvs"})")
                << "profile version 2 is not supported";
        QTest::newRow("another dialect")
                << QByteArray(R"({"format":"gnss-workbench-settings","version":1,)"
                              R"("dialect":"geostar","values":{"nav.ELEV":"5"}})")
                << "the profile is for dialect 'geostar', the receiver speaks 'nvs'";
        QTest::newRow("an unknown key") << nvsProfile(R"("rtk.ELGPS":"12","nav.ELEV":"5")")
                                        << "the nvs dialect cannot set: nav.ELEV";
        QTest::newRow("a number, not a string")
                << nvsProfile(R"("rtk.ELGPS":12)") << "rtk.ELGPS: the value must be a string";
    }
    void aProfileThatCannotBeAppliedIsRefusedSayingWhy() {
        QFETCH(QByteArray, json);
        QFETCH(QString, why);
        const DialectRegistry reg = makeBuiltinRegistry();
        Profile p;
        p.model = "untouched";
        QString error;
        QVERIFY(!profileFromJson(json, p, &error, reg.find("nvs")));
        QVERIFY2(error.contains(why), qPrintable(error));
        QCOMPARE(p.model, std::string("untouched")); // nothing of it taken
    }

    // A value is checked where it is about to be sent, not when the profile is read: a receiver
    // reports, and a profile carries, values its schema would not take (the VT002's unset user
    // datum), harmless while they are not sent.
    void aValueOutOfRangeIsReadAndRefusedWhenItWouldBeSent_data() {
        QTest::addColumn<QByteArray>("values");
        QTest::addColumn<QString>("why");
        QTest::newRow("all good") << QByteArray(R"("rtk.PVTRATE":"5","rtk.ELGPS":"12")") << "";
        QTest::newRow("out of range") << QByteArray(R"("rtk.PVTRATE":"5","rtk.ELGPS":"99")")
                                      << "rtk.ELGPS: 99 is out of range; accepted: 0..90";
        QTest::newRow("not one of the options")
                << QByteArray(R"("rtk.PVTRATE":"7")") << "rtk.PVTRATE";
        QTest::newRow("not a number") << QByteArray(R"("pps.duration":"long")") << "pps.duration";
        QTest::newRow("two of them") << QByteArray(R"("rtk.ELGPS":"99","rtk.ELGLO":"-1")")
                                     << "rtk.ELGPS: 99 is out of range; accepted: 0..90 deg; "
                                        "rtk.ELGLO: -1 is out of range";
    }
    void aValueOutOfRangeIsReadAndRefusedWhenItWouldBeSent() {
        QFETCH(QByteArray, values);
        QFETCH(QString, why);
        const DialectRegistry reg = makeBuiltinRegistry();
        Profile p;
        QString error;
        QVERIFY2(profileFromJson(nvsProfile(values), p, &error, reg.find("nvs")),
                 qPrintable(error));
        const QString refused = refusedValues(*reg.find("nvs"), p.values).join("; ");
        QVERIFY2(why.isEmpty() ? refused.isEmpty() : refused.startsWith(why), qPrintable(refused));
    }

    // Another model of the same dialect: refused when both models are known; another dialect
    // whatever the models.
    void aProfileOfAnotherModelIsNotForThisReceiver_data() {
        QTest::addColumn<int>("row");
        for (int i = 0; i < int(std::size(kModelRows)); ++i) QTest::newRow(kModelRows[i].name) << i;
    }
    void aProfileOfAnotherModelIsNotForThisReceiver() {
        QFETCH(int, row);
        const ModelRow &r = kModelRows[row];
        const DialectRegistry reg = makeBuiltinRegistry();
        Profile p;
        p.dialect = r.dialect;
        p.model = r.profileModel;
        const QString got = profileMismatch(p, reg.find("nvs"), r.receiverModel);
        QVERIFY2(*r.why ? got.startsWith(r.why) : got.isEmpty(), qPrintable(got));
    }

    // fuzz_profile_import found it: a key given by its spec name alone passed the schema check,
    // and the profile was accepted without it.
    void aKeyGivenByItsSpecNameIsKeptUnderTheSchemaKey() {
        const DialectRegistry reg = makeBuiltinRegistry();
        Profile p;
        QString error;
        QVERIFY2(profileFromJson(nvsProfile(R"("SYSGPS":"1","rtk.VRSMODE":"0")"), p, &error,
                                 reg.find("nvs")),
                 qPrintable(error));
        QCOMPARE(p.values.size(), std::size_t{2});
        QCOMPARE(p.values[0].key, std::string("rtk.SYSGPS"));
        QCOMPARE(p.values[0].value, std::string("1"));
        QCOMPARE(p.values[1].key, std::string("rtk.VRSMODE"));
    }

    void aSettingGivenTwiceIsRefused() {
        const DialectRegistry reg = makeBuiltinRegistry();
        Profile p;
        QString error;
        QVERIFY(!profileFromJson(nvsProfile(R"("SYSGPS":"1","rtk.SYSGPS":"0")"), p, &error,
                                 reg.find("nvs")));
        QVERIFY2(error.contains("rtk.SYSGPS: given twice"), qPrintable(error));
    }

    void withoutADialectKeysAreKeptAsWritten() {
        Profile p;
        QString error;
        QVERIFY2(profileFromJson(nvsProfile(R"("SYSGPS":"1")"), p, &error), qPrintable(error));
        QCOMPARE(p.values.size(), std::size_t{1});
        QCOMPARE(p.values[0].key, std::string("SYSGPS"));
    }
};

QTEST_APPLESS_MAIN(TstSettingsProfile)
#include "tst_settings_profile.moc"
