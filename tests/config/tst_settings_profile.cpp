// Settings profiles read from JSON (config::profileFromJson, what loadProfile reads from a file):
// keys as users write them, and nothing dropped on the way.
#include "dialects.h"
#include "settings_profile.h"

#include <QTest>

using namespace gnss;
using namespace gnss::config;

namespace {

QByteArray nvsProfile(const QByteArray &values) {
    return R"({"format":"gnss-workbench-settings","version":1,"dialect":"nvs","values":{)" +
           values + "}}";
}

} // namespace

class TstSettingsProfile : public QObject {
    Q_OBJECT
private slots:
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
