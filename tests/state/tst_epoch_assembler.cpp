// EpochAssembler: one snapshot per fix time, GSV groups whole or not at all.
#include "builtin/dialects.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "state/epoch_assembler.h"

#include <QTest>

using namespace gnss;

namespace {

std::vector<Epoch> epochsOf(const std::vector<std::string> &bodies, const char *dialect = "auto") {
    static const DialectRegistry reg = makeBuiltinRegistry();
    StreamDecoder dec(reg, {.dialect = dialect});
    EpochAssembler asm_(dec.dialect());
    std::vector<Epoch> out;
    auto onEpoch = [&](const Epoch &e) { out.push_back(e); };
    for (const auto &b : bodies) {
        const std::string line = buildSentence(b) + "\r\n";
        dec.feed(line, [&](const SentenceEvent &ev) {
            if (ev.message) asm_.add(ev.sentence, *ev.message, onEpoch);
        });
    }
    asm_.flush(onEpoch);
    return out;
}

// A 3D fix at `time` (hhmmss.ss) with four satellites, 545.4 m above the geoid.
std::string gga(const std::string &time, const std::string &talker = "GP") {
    return talker + "GGA," + time + ",4807.038,N,01131.000,E,1,04,0.9,545.4,M,46.9,M,,";
}

const SatelliteInView *find(const Epoch &e, Constellation c, int prn, int signal = 0) {
    for (const auto &s : e.satellites)
        if (s.sat.system == c && s.sat.prn == prn && s.signalId == signal) return &s;
    return nullptr;
}

} // namespace

class TstEpochAssembler : public QObject {
    Q_OBJECT
private slots:
    void sentencesOfOneFixTimeMakeOneEpoch() {
        const auto epochs = epochsOf({
                "GPRMC,120000.00,A,4807.038,N,01131.000,E,1.0,90.0,230394,,,A",
                gga("120000.00"),
                "GPGSA,A,3,01,02,03,04,,,,,,,,,1.8,0.9,1.5",
                "GPGSV,2,1,05,01,40,083,46,02,17,308,41,03,07,344,39,04,22,228,45",
                "GPGSV,2,2,05,05,10,010,",
                "GPRMC,120001.00,A,4807.038,N,01131.000,E,1.0,90.0,230394,,,A",
                gga("120001.00"),
        });
        QCOMPARE(epochs.size(), std::size_t(2));
        const Epoch &e = epochs[0];
        QCOMPARE(QString::fromStdString(e.timeText()), QString("1994-03-23T12:00:00.000Z"));
        QCOMPARE(int(e.fix), int(FixType::Fix3D));
        QCOMPARE(*e.satsUsed, 4);
        QCOMPARE(*e.pdop, 1.8);
        QCOMPARE(e.altEllipsoid().value(), 545.4 + 46.9);
        QCOMPARE(e.satellites.size(), std::size_t(5));
        QVERIFY(find(e, Constellation::Gps, 1)->used);
        QVERIFY(!find(e, Constellation::Gps, 5)->used);
        QVERIFY(!find(e, Constellation::Gps, 5)->snr);
        // The sky carries over into the next epoch.
        QCOMPARE(epochs[1].satellites.size(), std::size_t(5));
    }

    void incompleteGsvGroupIsNotApplied() {
        const auto epochs = epochsOf({
                gga("120000.00"),
                "GPGSV,2,1,05,01,40,083,46,02,17,308,41,03,07,344,39,04,22,228,45",
                // part 2 lost
                gga("120001.00"),
                "GPGSV,2,2,05,05,10,010,",
                gga("120002.00"),
        });
        QCOMPARE(epochs.size(), std::size_t(3));
        for (const auto &e : epochs) QVERIFY(e.satellites.empty());
    }

    void satelliteOnSeveralSignalsKeepsOneEntryPerSignal() {
        const auto epochs = epochsOf({
                gga("120000.00", "GN"),
                "GPGSV,1,1,02,05,40,083,46,07,20,100,40,1",
                "GPGSV,1,1,01,05,40,083,38,8",
                "GNGSA,A,3,05,07,,,,,,,,,,,1.8,0.9,1.5,1",
        });
        QCOMPARE(epochs.size(), std::size_t(1));
        const Epoch &e = epochs[0];
        QCOMPARE(e.satellites.size(), std::size_t(3));
        QCOMPARE(*find(e, Constellation::Gps, 5, 1)->snr, 46);
        QCOMPARE(*find(e, Constellation::Gps, 5, 8)->snr, 38);
        QVERIFY(find(e, Constellation::Gps, 5, 8)->used);
    }

    void fixTypeFollowsQualityModeAndGsa_data() {
        QTest::addColumn<QString>("first");
        QTest::addColumn<QString>("second");
        QTest::addColumn<int>("fix");
        const QString gga = "GPGGA,120000.00,4807.038,N,01131.000,E,%1,04,0.9,545.4,M,46.9,M,,";
        QTest::newRow("rtk fixed") << gga.arg(4) << "" << int(FixType::RtkFixed);
        QTest::newRow("rtk float") << gga.arg(5) << "" << int(FixType::RtkFloat);
        QTest::newRow("dgnss") << gga.arg(2) << "" << int(FixType::Dgnss);
        QTest::newRow("estimated") << gga.arg(6) << "" << int(FixType::Estimated);
        QTest::newRow("no fix") << gga.arg(0) << "" << int(FixType::None);
        QTest::newRow("2D from GSA")
                << gga.arg(1) << "GPGSA,A,2,01,02,03,,,,,,,,,,1.8,0.9,1.5" << int(FixType::Fix2D);
        QTest::newRow("RMC mode R")
                << "GPRMC,120000.00,A,4807.038,N,01131.000,E,1.0,90.0,230394,,,R"
                << "" << int(FixType::RtkFixed);
        QTest::newRow("RMC void") << "GPRMC,120000.00,V,,,,,,,230394,,,N"
                                  << "" << int(FixType::None);
        QTest::newRow("GNS modes")
                << "GNGNS,120000.00,4807.038,N,01131.000,E,FR,10,0.8,182.2,14.4,,,V"
                << "" << int(FixType::RtkFixed);
    }
    void fixTypeFollowsQualityModeAndGsa() {
        QFETCH(QString, first);
        QFETCH(QString, second);
        QFETCH(int, fix);
        std::vector<std::string> b{first.toStdString()};
        if (!second.isEmpty()) b.push_back(second.toStdString());
        const auto epochs = epochsOf(b);
        QCOMPARE(epochs.size(), std::size_t(1));
        QCOMPARE(int(epochs[0].fix), fix);
    }

    void vendorFixKindsCarryTheirNote() {
        // GeoS-5: GGA quality 9 and mode letter G are GeoPath, shown as 3D with a note.
        auto epochs = epochsOf(
                {"GPGGA,040717.00,5550.610226,N,03732.250730,E,9,18,0.6,00187.429,M,0014.442,M,,"},
                "geostar");
        QCOMPARE(int(epochs[0].fix), int(FixType::Fix3D));
        QCOMPARE(QString::fromStdString(epochs[0].fixNote), QString("GeoPath"));
        epochs = epochsOf(
                {"GNRMC,102014.00,A,5550.608252,N,03732.248871,E,000.00000,092.9,300518,,,G,V"},
                "geostar");
        QCOMPARE(int(epochs[0].fix), int(FixType::Fix3D));
        QCOMPARE(QString::fromStdString(epochs[0].fixNote), QString("GeoPath"));
        // Quality 7 is a fixed (manual) position there.
        epochs = epochsOf(
                {"GPGGA,040717.00,5550.610226,N,03732.250730,E,7,18,0.6,00187.429,M,0014.442,M,,"},
                "geostar");
        QCOMPARE(int(epochs[0].fix), int(FixType::Manual));
        QVERIFY(epochs[0].fixNote.empty());
    }

    void dopsOfASlowerGsaHoldUntilTheNext() {
        const auto epochs = epochsOf({
                gga("120000.00"),
                "GPGSA,A,3,01,02,03,04,,,,,,,,,1.8,0.9,1.5",
                gga("120001.00"),
                gga("120002.00"),
        });
        QCOMPARE(epochs.size(), std::size_t(3));
        QCOMPARE(*epochs[2].pdop, 1.8);
        QCOMPARE(*epochs[2].vdop, 1.5);
    }

    void timeWithoutDateStaysTimeOfDay() {
        const auto epochs = epochsOf({gga("235959.50")});
        QCOMPARE(QString::fromStdString(epochs[0].timeText()), QString("23:59:59.500"));
    }
};

QTEST_APPLESS_MAIN(TstEpochAssembler)
#include "tst_epoch_assembler.moc"
