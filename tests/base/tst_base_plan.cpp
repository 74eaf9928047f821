// A base station by roles (base/base_roles.h, base_plan.h): which built-in dialects can be a base,
// and the settings a request comes to, refused with a clear reason before anything is sent.
#include "base/base_plan.h"
#include "builtin/dialects.h"

#include <QTest>

using namespace gnss;
using namespace gnss::base;

namespace {

std::string valueOf(const BasePlan &p, std::string_view key) {
    for (const auto &kv : p.values)
        if (kv.key == key) return kv.value;
    return "(none)";
}

auto nothingKnown = [](std::string_view) -> std::optional<std::string> { return std::nullopt; };

} // namespace

class TstBasePlan : public QObject {
    Q_OBJECT
    DialectRegistry registry_ = makeBuiltinRegistry();

    BaseRoles nvs() {
        const auto r = baseRoles(*registry_.find("nvs"));
        if (!r) qFatal("the NV08C-RTK can be a base");
        return *r;
    }

private slots:
    void onlyTheRtkReceiverCanBeABase_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<bool>("base");
        QTest::newRow("NV08C-RTK") << "nvs" << true;
        QTest::newRow("GeoS-5") << "geostar" << false;
        QTest::newRow("VT002") << "nemerix" << false;
        QTest::newRow("NMEA") << "nmea" << false;
    }
    void onlyTheRtkReceiverCanBeABase() {
        QFETCH(QString, dialect);
        QFETCH(bool, base);
        QCOMPARE(canBeBase(*registry_.find(dialect.toStdString())), base);
    }

    void theRolesOfTheNvsSchema() {
        const BaseRoles r = nvs();
        QCOMPARE(r.modeValue(OptionMeaning::BaseFixed), std::string_view("1"));
        QCOMPARE(r.modeValue(OptionMeaning::BaseAveraging), std::string_view("3"));
        QCOMPARE(r.modeMeaning("2"), OptionMeaning::Rover);
        QCOMPARE(r.modeMeaning("4"), OptionMeaning::Rover);
        QCOMPARE(r.modeMeaning("9"), OptionMeaning::None);
        QVERIFY(r.canAverage() && r.station && r.rtcmInterval && r.threshold && r.nmeaPosition);
        QCOMPARE(r.rtcmPorts(), (std::vector<int>{1, 2, 3}));
        QCOMPARE(r.protocolValue(2, OptionMeaning::Rtcm3), std::string_view("7"));
        QVERIFY(r.speedOf(2) && r.speedOf(1));
        // Read back: every readable one (the ports' settings are write-only).
        const auto keys = r.keys();
        QVERIFY(keys.size() >= 8);
        QVERIFY(std::ranges::find(keys, std::string(r.position->key)) != keys.end());
    }

    void aFixedBaseWithItsPortAndStation() {
        BaseRequest q;
        q.position = wgs84::Ecef{2849848.3852, 2196137.039, 5249039.7734};
        q.station = 321;
        q.rtcmInterval = 2;
        q.rtcmPort = 2;
        const BaseRoles r = nvs();
        const BasePlan p = planBase(r, q, nothingKnown);
        QVERIFY2(p.ok(), p.error.c_str());
        QCOMPARE(valueOf(p, r.mode->key), std::string("1"));
        QCOMPARE(valueOf(p, r.position->key), std::string("2849848.385,2196137.039,5249039.773"));
        QCOMPARE(valueOf(p, r.station->key), std::string("321"));
        QCOMPARE(valueOf(p, r.rtcmInterval->key), std::string("2"));
        QCOMPARE(valueOf(p, r.protocolOf(2)->key), std::string("7"));
        QCOMPARE(valueOf(p, r.speedOf(2)->key), std::string("115200")); // the schema's default
        // A known speed is kept; one given wins.
        auto known = [&](std::string_view key) -> std::optional<std::string> {
            return key == r.speedOf(2)->key ? std::optional<std::string>("38400") : std::nullopt;
        };
        QCOMPARE(valueOf(planBase(r, q, known), r.speedOf(2)->key), std::string("38400"));
        q.rtcmPortSpeed = 57600;
        QCOMPARE(valueOf(planBase(r, q, known), r.speedOf(2)->key), std::string("57600"));
    }

    void theReceiverAveraging() {
        BaseRequest q;
        q.kind = BaseRequest::Kind::Averaging;
        q.averagingMinutes = 5;
        q.averagingInput = "2";
        const BaseRoles r = nvs();
        const BasePlan p = planBase(r, q, nothingKnown);
        QVERIFY2(p.ok(), p.error.c_str());
        QCOMPARE(valueOf(p, r.mode->key), std::string("3"));
        QCOMPARE(valueOf(p, r.averagingMinutes->key), std::string("5"));
        QCOMPARE(valueOf(p, r.averagingInput->key), std::string("2"));
        QCOMPARE(valueOf(p, r.position->key), std::string("(none)"));
    }

    void refusals_data() {
        QTest::addColumn<int>("what");
        QTest::addColumn<QString>("says");
        QTest::newRow("no position") << 0 << "needs its position";
        QTest::newRow("kilometres") << 1 << "not near the Earth's surface";
        QTest::newRow("station 4096") << 2 << "--station";
        QTest::newRow("interval 3 s") << 3 << "--rtcm-interval";
        QTest::newRow("port 4") << 4 << "no port 4 can carry RTCM 3 (1, 2, 3 can)";
        QTest::newRow("averaging 0 min") << 5 << "--minutes";
    }
    void refusals() {
        QFETCH(int, what);
        QFETCH(QString, says);
        BaseRequest q;
        q.position = wgs84::Ecef{2849848.3852, 2196137.039, 5249039.7734};
        switch (what) {
        case 0: q.position.reset(); break;
        case 1: q.position = wgs84::Ecef{2849.848, 2196.137, 5249.039}; break;
        case 2: q.station = 4096; break;
        case 3: q.rtcmInterval = 3; break;
        case 4: q.rtcmPort = 4; break;
        case 5:
            q.kind = BaseRequest::Kind::Averaging;
            q.averagingMinutes = 0;
            break;
        }
        const BasePlan p = planBase(nvs(), q, nothingKnown);
        QVERIFY(!p.ok());
        QVERIFY(p.values.empty());
        QVERIFY2(QString::fromStdString(p.error).contains(says), p.error.c_str());
    }
};

QTEST_GUILESS_MAIN(TstBasePlan)
#include "tst_base_plan.moc"
