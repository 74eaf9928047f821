// The standard sentence encoders: byte-exact output with correct checksums, and a round trip
// through the core decoders that gives back every field.
#include "core/sentence.h"
#include "core/sentence_builder.h"
#include "nmea/nmea_encoders.h"

#include <QTest>

#include <functional>
#include <string>

using namespace gnss;
using namespace gnss::nmea;

namespace {

// Decodes one sentence with the standard table; returns the message through `use`.
template <class T>
bool decodeAs(const std::string &line, DecodeFn fn, const std::function<void(const T &)> &use) {
    Sentence s;
    if (!s.parse(line) || s.checksum() != ChecksumStatus::Ok) return false;
    bool got = false;
    // Named, so that FunctionRef refers to it; a temporary would be copied into the reference
    // (FunctionRef keeps small trivially copyable temporaries, and refuses others at compile time).
    auto onMessage = [&](const Message &m) {
        if (const T *t = message_cast<T>(m)) {
            use(*t);
            got = true;
        }
    };
    DecodeContext ctx(nullptr, onMessage);
    return fn(s, ctx) && got;
}

} // namespace

class TstNmeaEncoders : public QObject {
    Q_OBJECT
private slots:
    void ggaIsByteExactWithChecksum() {
        Gga m;
        m.time = timeOfDay(12 * 3600 + 35 * 60 + 19, 2);
        m.lat = 48 + 7.038 / 60;
        m.lon = 11 + 31.0 / 60;
        m.quality = 1;
        m.satsUsed = 8;
        m.hdop = 0.9;
        m.altMsl = 545.4;
        m.geoidSep = 46.9;
        const std::string s = encodeGga("GP", m, EncodeFormat{2, 3});
        QCOMPARE(QByteArray::fromStdString(s),
                 QByteArray::fromStdString(buildSentence(
                         "GPGGA,123519.00,4807.038,N,01131.000,E,1,08,0.9,545.400,M,46.900,M,,")));
    }
    void southWestAndRoundingNeverPrintSixtyMinutes() {
        QCOMPARE(QString::fromStdString(formatLatitude(-33.99999999, 4)), QString("3400.0000,S"));
        QCOMPARE(QString::fromStdString(formatLongitude(-70.5, 2)), QString("07030.00,W"));
        QCOMPARE(QString::fromStdString(formatLatitude(std::nullopt, 4)), QString(","));
        QCOMPARE(QString::fromStdString(formatTime(timeOfDay(86399.999, 2), 2)),
                 QString("000000.00")); // rounds over midnight, never "235960"
        QCOMPARE(QString::fromStdString(formatTime(timeOfDay(3723.456, 0), 0)), QString("010203"));
    }
    void ggaRoundTripsThroughTheDecoder() {
        Gga m;
        m.time = timeOfDay(36000.2, 2);
        m.lat = -55.75123456;
        m.lon = 137.61841234;
        m.quality = 4;
        m.satsUsed = 17;
        m.hdop = 0.7;
        m.altMsl = 152.123;
        m.geoidSep = -14.6;
        m.dgpsAge = 1.2;
        m.dgpsStation = 2;
        const std::string s = encodeGga("GN", m, EncodeFormat{2, 7});
        QVERIFY(decodeAs<Gga>(s, decodeGga, [&](const Gga &d) {
            QCOMPARE(d.time->nanos, m.time->nanos);
            QVERIFY(std::abs(*d.lat - *m.lat) < 1e-8);
            QVERIFY(std::abs(*d.lon - *m.lon) < 1e-8);
            QCOMPARE(*d.quality, 4);
            QCOMPARE(*d.satsUsed, 17);
            QCOMPARE(*d.hdop, 0.7);
            QCOMPARE(*d.altMsl, 152.123);
            QCOMPARE(*d.geoidSep, -14.6);
            QCOMPARE(*d.dgpsAge, 1.2);
            QCOMPARE(*d.dgpsStation, 2);
        }));
    }
    void emptyGgaRoundTripsAsEmptyFields() {
        Gga m;
        m.time = timeOfDay(1, 2);
        m.quality = 0;
        m.satsUsed = 0;
        const std::string s = encodeGga("GP", m);
        QVERIFY(decodeAs<Gga>(s, decodeGga, [](const Gga &d) {
            QVERIFY(!d.lat && !d.lon && !d.hdop && !d.altMsl);
            QCOMPARE(*d.quality, 0);
        }));
    }
    void rmcRoundTrips() {
        Rmc m;
        m.time = timeOfDay(45000, 2);
        m.status = 'A';
        m.lat = 55.5;
        m.lon = -37.25;
        m.sogKnots = 0.12;
        m.cog = 271.5;
        m.date = Date{2024, 3, 15};
        m.magVar = -3.5;
        m.mode = 'R';
        m.navStatus = 'S';
        QVERIFY(decodeAs<Rmc>(encodeRmc("GN", m), decodeRmc, [&](const Rmc &d) {
            QCOMPARE(*d.status, 'A');
            QVERIFY(std::abs(*d.lat - 55.5) < 1e-9);
            QVERIFY(std::abs(*d.lon + 37.25) < 1e-9);
            QCOMPARE(*d.sogKnots, 0.12);
            QCOMPARE(*d.cog, 271.5);
            QVERIFY(*d.date == (Date{2024, 3, 15}));
            QCOMPARE(*d.magVar, -3.5);
            QCOMPARE(*d.mode, 'R');
            QCOMPARE(*d.navStatus, 'S');
        }));
    }
    void gsaRoundTripsIdsDopsAndSystemId() {
        Gsa m;
        m.mode = 'A';
        m.fix = 3;
        for (int id : {65, 66, 72, 80}) m.ids[m.idCount++] = id;
        m.pdop = 1.5;
        m.hdop = 0.8;
        m.vdop = 1.2;
        m.systemId = 2;
        const std::string s = encodeGsa("GN", m);
        QVERIFY(decodeAs<Gsa>(s, decodeGsa, [&](const Gsa &d) {
            QCOMPARE(d.idCount, std::size_t(4));
            QCOMPARE(d.ids[2], 72);
            QVERIFY(d.satellites[0].system == Constellation::Glonass);
            QCOMPARE(d.satellites[0].prn, 1);
            QCOMPARE(*d.pdop, 1.5);
            QCOMPARE(*d.vdop, 1.2);
            QCOMPARE(*d.systemId, 2);
        }));
        Gsa noSystem = m;
        noSystem.systemId.reset();
        QVERIFY(decodeAs<Gsa>(encodeGsa("GN", noSystem), decodeGsa,
                              [](const Gsa &d) { QVERIFY(!d.systemId); }));
    }
    void gsvGroupSplitsByFourAndRoundTrips() {
        std::vector<GsvSatellite> sats;
        for (int i = 1; i <= 9; ++i) {
            GsvSatellite g;
            g.id = i;
            g.elevation = 5 * i;
            g.azimuth = 40 * i;
            if (i % 3) g.snr = 30 + i;
            sats.push_back(g);
        }
        const auto lines = encodeGsvGroup("GP", sats, 1);
        QCOMPARE(lines.size(), std::size_t(3));
        int seen = 0;
        for (std::size_t k = 0; k < lines.size(); ++k) {
            QVERIFY(decodeAs<Gsv>(lines[k], decodeGsv, [&](const Gsv &d) {
                QCOMPARE(*d.total, 3);
                QCOMPARE(*d.index, int(k) + 1);
                QCOMPARE(*d.inView, 9);
                QCOMPARE(*d.signalId, 1);
                for (std::size_t i = 0; i < d.satelliteCount; ++i, ++seen) {
                    const auto &s = d.satellites[i];
                    QCOMPARE(s.id, seen + 1);
                    QCOMPARE(*s.elevation, 5 * (seen + 1));
                    QCOMPARE(*s.azimuth, 40 * (seen + 1));
                    QCOMPARE(s.snr.has_value(), ((seen + 1) % 3) != 0);
                }
            }));
        }
        QCOMPARE(seen, 9);
        QCOMPARE(encodeGsvGroup("GL", {}).size(), std::size_t(1)); // "no satellites" still says so
    }
    void vtgZdaGllGnsHdtGstTxtRoundTrip() {
        Vtg v;
        v.cogTrue = 12.5;
        v.sogKnots = 1.25;
        v.sogKmh = 2.32;
        v.mode = 'A';
        QVERIFY(decodeAs<Vtg>(encodeVtg("GP", v), decodeVtg, [](const Vtg &d) {
            QCOMPARE(*d.cogTrue, 12.5);
            QVERIFY(!d.cogMagnetic);
            QCOMPARE(*d.sogKmh, 2.32);
            QCOMPARE(*d.mode, 'A');
        }));
        Zda z;
        z.time = timeOfDay(3600, 2);
        z.date = Date{2024, 12, 31};
        z.tzHours = -3;
        z.tzMinutes = 30;
        QVERIFY(decodeAs<Zda>(encodeZda("GN", z), decodeZda, [](const Zda &d) {
            QVERIFY(*d.date == (Date{2024, 12, 31}));
            QCOMPARE(*d.tzHours, -3);
            QCOMPARE(*d.tzMinutes, 30);
        }));
        Gll l;
        l.lat = 10.5;
        l.lon = 20.25;
        l.time = timeOfDay(60, 1);
        l.status = 'A';
        l.mode = 'D';
        QVERIFY(decodeAs<Gll>(encodeGll("GL", l, {1, 5}), decodeGll, [](const Gll &d) {
            QCOMPARE(*d.status, 'A');
            QCOMPARE(*d.mode, 'D');
            QVERIFY(std::abs(*d.lon - 20.25) < 1e-9);
        }));
        Gns g;
        g.time = timeOfDay(100, 2);
        g.lat = 1;
        g.lon = 2;
        g.mode = "RRNN";
        g.satsUsed = 14;
        g.hdop = 0.6;
        g.altMsl = 100;
        g.geoidSep = 10;
        g.navStatus = 'S';
        QVERIFY(decodeAs<Gns>(encodeGns("GN", g), decodeGns, [](const Gns &d) {
            QCOMPARE(QString::fromLatin1(d.mode.data(), int(d.mode.size())), QString("RRNN"));
            QCOMPARE(*d.satsUsed, 14);
            QCOMPARE(*d.navStatus, 'S');
        }));
        Hdt h;
        h.heading = 40.61;
        QVERIFY(decodeAs<Hdt>(encodeHdt("GP", h), decodeHdt,
                              [](const Hdt &d) { QCOMPARE(*d.heading, 40.61); }));
        Hdt none;
        QCOMPARE(QString::fromStdString(encodeHdt("GP", none)),
                 QString::fromStdString(buildSentence("GPHDT,,T")));
        Gst st;
        st.time = timeOfDay(5, 2);
        st.rms = 0.5;
        st.sdLat = 0.011;
        st.sdLon = 0.012;
        st.sdAlt = 0.025;
        QVERIFY(decodeAs<Gst>(encodeGst("GN", st), decodeGst, [](const Gst &d) {
            QCOMPARE(*d.sdLat, 0.011);
            QCOMPARE(*d.sdAlt, 0.025);
            QVERIFY(!d.sdMajor);
        }));
        Txt t;
        t.total = 1;
        t.number = 1;
        t.id = 2;
        t.text = "SIMULATED RECEIVER";
        QVERIFY(decodeAs<Txt>(encodeTxt("GP", t), decodeTxt, [](const Txt &d) {
            QCOMPARE(QString::fromLatin1(d.text.data(), int(d.text.size())),
                     QString("SIMULATED RECEIVER"));
        }));
    }
};

QTEST_APPLESS_MAIN(TstNmeaEncoders)
#include "tst_nmea_encoders.moc"
