// Ephemerides 1019, 1020, 1042, 1044, 1045, 1046: lengths as the standard gives them, the
// identifying fields where the standard puts them, round trips, truncations.
#include "rtcm/bit_reader.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm_test_support.h"

#include <QTest>

using namespace gnss::rtcm;
using namespace rtcm_test;

Q_DECLARE_METATYPE(Ephemeris)

namespace {

// Each message's fields at or near their limits; ephemeris(satellite, week, IODE, IODC, toc, toe,
// health).
Ephemeris sample(unsigned number) {
    Ephemeris e;
    switch (number) {
    case 1019: return ephemeris(31, 1023, 255, 1023, 604784, 7200, 63); // toc 37799 × 16 s
    case 1042: return ephemeris(63, 8191, 31, 17, 604792, 8, 1);        // toc in 8 s units
    case 1044: return ephemeris(10, 2, 77, 589, 16, 604784, 33);
    case 1045:
        e = ephemeris(36, 4095, 1023, std::nullopt, 604740, 600, std::nullopt); // 60 s units
        e.e5aHealth = 3, e.e5aValidity = 1;
        break;
    case 1046:
        e = ephemeris(1, 1234, 99, std::nullopt, 60, 120, std::nullopt);
        e.e5bHealth = 2, e.e5bValidity = 0, e.e1bHealth = 1, e.e1bValidity = 1;
        break;
    case 1020:
        e.satellite = 24, e.health = 1;
        e.frequencyChannel = -7;
        e.tkSeconds = 23 * 3600 + 59 * 60 + 30;
        e.tbMinutes = 96 * 15 - 15;
        break;
    }
    return e;
}

} // namespace

class TstRtcmEphemeris : public QObject {
    Q_OBJECT
private slots:
    void ephemerisRoundTrips_data() {
        QTest::addColumn<uint>("number");
        QTest::addColumn<int>("length"); // payload bytes, from the standard's bit counts
        QTest::addColumn<QString>("system");
        QTest::newRow("1019 GPS, 488 bits") << 1019u << 61 << "GPS";
        QTest::newRow("1020 GLONASS, 360 bits") << 1020u << 45 << "GLONASS";
        QTest::newRow("1042 BeiDou, 511 bits") << 1042u << 64 << "BeiDou";
        QTest::newRow("1044 QZSS, 485 bits") << 1044u << 61 << "QZSS";
        QTest::newRow("1045 Galileo F/NAV, 496 bits") << 1045u << 62 << "Galileo";
        QTest::newRow("1046 Galileo I/NAV, 504 bits") << 1046u << 63 << "Galileo";
    }
    void ephemerisRoundTrips() {
        QFETCH(uint, number);
        QFETCH(int, length);
        QFETCH(QString, system);
        const Ephemeris e = sample(number);
        const RtcmMessage m = decodeFrame(encodeEphemeris(number, e));
        QCOMPARE(m.number, number);
        QCOMPARE(m.length, std::size_t(length));
        QVERIFY2(m.error.empty(), std::string(m.error).c_str());
        QVERIFY(!m.station); // ephemerides carry no station id
        const auto *d = std::get_if<Ephemeris>(&m.body);
        QVERIFY(d);
        QCOMPARE(QString::fromStdString(std::string(systemName(d->system))), system);
        QCOMPARE(d->satellite, e.satellite);
        QCOMPARE(d->prn, number == 1044 ? 192 + e.satellite : e.satellite);
        QCOMPARE(d->week, e.week);
        QCOMPARE(d->iode, e.iode);
        QCOMPARE(d->iodc, e.iodc);
        QCOMPARE(d->tocSeconds, e.tocSeconds);
        QCOMPARE(d->toeSeconds, e.toeSeconds);
        QCOMPARE(d->health, e.health);
        QCOMPARE(d->frequencyChannel, e.frequencyChannel);
        QCOMPARE(d->tkSeconds, e.tkSeconds);
        QCOMPARE(d->tbMinutes, e.tbMinutes);
        QCOMPARE(d->e5aHealth, e.e5aHealth);
        QCOMPARE(d->e5aValidity, e.e5aValidity);
        QCOMPARE(d->e5bHealth, e.e5bHealth);
        QCOMPARE(d->e5bValidity, e.e5bValidity);
        QCOMPARE(d->e1bHealth, e.e1bHealth);
        QCOMPARE(d->e1bValidity, e.e1bValidity);
    }

    // Bit offsets summed by hand from the standard's field tables (DF002 at 0), read straight from
    // the encoder's payload: a slip in both encoder and decoder would still show here.
    void fieldsSitWhereTheStandardPutsThem_data() {
        QTest::addColumn<uint>("number");
        QTest::addColumn<int>("offset");
        QTest::addColumn<int>("width");
        QTest::addColumn<qulonglong>("value");
        QTest::newRow("1019 satellite") << 1019u << 12 << 6 << 31ULL;
        QTest::newRow("1019 week") << 1019u << 18 << 10 << 1023ULL;
        QTest::newRow("1019 IODE") << 1019u << 48 << 8 << 255ULL;
        QTest::newRow("1019 toc") << 1019u << 56 << 16 << 37799ULL;
        QTest::newRow("1019 IODC") << 1019u << 118 << 10 << 1023ULL;
        QTest::newRow("1019 toe") << 1019u << 288 << 16 << 450ULL;
        QTest::newRow("1019 health") << 1019u << 480 << 6 << 63ULL;
        QTest::newRow("1020 slot") << 1020u << 12 << 6 << 24ULL;
        QTest::newRow("1020 frequency channel") << 1020u << 18 << 5 << 0ULL;
        QTest::newRow("1020 tk hours") << 1020u << 27 << 5 << 23ULL;
        QTest::newRow("1020 tk minutes") << 1020u << 32 << 6 << 59ULL;
        QTest::newRow("1020 tk 30 s") << 1020u << 38 << 1 << 1ULL;
        QTest::newRow("1020 Bn") << 1020u << 39 << 1 << 1ULL;
        QTest::newRow("1020 tb") << 1020u << 41 << 7 << 95ULL;
        QTest::newRow("1042 satellite") << 1042u << 12 << 6 << 63ULL;
        QTest::newRow("1042 week") << 1042u << 18 << 13 << 8191ULL;
        QTest::newRow("1042 AODE") << 1042u << 49 << 5 << 31ULL;
        QTest::newRow("1042 toc") << 1042u << 54 << 17 << 75599ULL;
        QTest::newRow("1042 AODC") << 1042u << 128 << 5 << 17ULL;
        QTest::newRow("1042 toe") << 1042u << 299 << 17 << 1ULL;
        QTest::newRow("1042 health") << 1042u << 510 << 1 << 1ULL;
        QTest::newRow("1044 satellite") << 1044u << 12 << 4 << 10ULL;
        QTest::newRow("1044 toc") << 1044u << 16 << 16 << 1ULL;
        QTest::newRow("1044 IODE") << 1044u << 78 << 8 << 77ULL;
        QTest::newRow("1044 toe") << 1044u << 246 << 16 << 37799ULL;
        QTest::newRow("1044 week") << 1044u << 446 << 10 << 2ULL;
        QTest::newRow("1044 health") << 1044u << 460 << 6 << 33ULL;
        QTest::newRow("1044 IODC") << 1044u << 474 << 10 << 589ULL;
        QTest::newRow("1045 satellite") << 1045u << 12 << 6 << 36ULL;
        QTest::newRow("1045 week") << 1045u << 18 << 12 << 4095ULL;
        QTest::newRow("1045 IODnav") << 1045u << 30 << 10 << 1023ULL;
        QTest::newRow("1045 toc") << 1045u << 62 << 14 << 10079ULL;
        QTest::newRow("1045 toe") << 1045u << 294 << 14 << 10ULL;
        QTest::newRow("1045 E5a health") << 1045u << 486 << 2 << 3ULL;
        QTest::newRow("1045 E5a validity") << 1045u << 488 << 1 << 1ULL;
        QTest::newRow("1046 E5b health") << 1046u << 496 << 2 << 2ULL;
        QTest::newRow("1046 E1-B health") << 1046u << 499 << 2 << 1ULL;
        QTest::newRow("1046 E1-B validity") << 1046u << 501 << 1 << 1ULL;
    }
    void fieldsSitWhereTheStandardPutsThem() {
        QFETCH(uint, number);
        QFETCH(int, offset);
        QFETCH(int, width);
        QFETCH(qulonglong, value);
        const auto payload = ephemerisPayload(number, sample(number));
        BitReader r(payload, std::size_t(offset));
        QCOMPARE(r.u(unsigned(width)), std::uint64_t(value));
        BitReader number12(payload);
        QCOMPARE(number12.u(12), std::uint64_t(number));
    }

    void everyTruncationIsAnErrorNotACrash() {
        for (const unsigned number : {1019u, 1020u, 1042u, 1044u, 1045u, 1046u}) {
            const auto payload = ephemerisPayload(number, sample(number));
            for (std::size_t n = 0; n < payload.size(); ++n) {
                const RtcmMessage m = decodeMessage(std::span(payload).first(n));
                QVERIFY(!m.error.empty());
                QVERIFY(std::holds_alternative<std::monostate>(m.body));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TstRtcmEphemeris)
#include "tst_rtcm_ephemeris.moc"
