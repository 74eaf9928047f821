// RQUERY's three words (tables 7-9 of section 3.11): the spec example decodes to the bits the
// tables give, every single bit of every table lands in its own named field, and each word is
// built back from its fields bit by bit (encode: the inverse of decode).
#include "decode_helper.h"
#include "geostar/geostar_status_words.h"

#include <QTest>

using namespace gnss::geostar;

namespace {

const char *kExample = "$GPSGG,RQUERY,GEOS-5,V.5.102,100518,00083037,802DC097,F7FF8064*5C";

QJsonObject exampleWord(const char *word) {
    gnss::DecoderOptions o;
    o.dialect = "geostar";
    const auto d = gnss::test::decodeOne(kExample, o);
    return d.data[word].toObject();
}

// fn(W{}) with W the word named "status", "config1" or "config2".
template <class Fn> auto forWord(const QString &word, Fn fn) {
    if (word == "status") return fn(StatusWord{});
    if (word == "config1") return fn(ConfigRegister1{});
    return fn(ConfigRegister2{});
}

QJsonObject wordJson(const char *word, std::uint32_t v) {
    std::string json;
    gnss::JsonWriter w(json);
    forWord(word, [&](auto type) { decltype(type)::decode(v).writeJson(w); });
    return QJsonDocument::fromJson(QByteArray::fromStdString(json)).object();
}

// decode(v).encode(), with the raw word kept (reserved bits come back) or cleared (the fields
// alone: what a receiver filling the struct field by field gets).
EncodedWord reencoded(const QString &word, std::uint32_t v, bool keepRaw) {
    return forWord(word, [&](auto type) {
        auto w = decltype(type)::decode(v);
        if (!keepRaw) w.raw = 0;
        return w.encode();
    });
}

std::uint32_t reservedMask(const QString &word) {
    return forWord(word, [](auto type) { return std::uint32_t(decltype(type)::kReservedMask); });
}

} // namespace

class TstGeostarStatusWords : public QObject {
    Q_OBJECT
private slots:
    void rqueryExampleDecodesToTheTableBits_data();
    void rqueryExampleDecodesToTheTableBits();
    void eachSingleBitSetsItsNamedField_data();
    void eachSingleBitSetsItsNamedField();
    void receiverTypesOfTable9();
    void multiBitFieldsDecodeEveryValue();
    void encodeIsTheInverseOfDecode_data();
    void encodeIsTheInverseOfDecode();
    void theFieldsAloneGiveEveryBitButTheReservedOnes_data();
    void theFieldsAloneGiveEveryBitButTheReservedOnes();
    void everyValueOfAMultiBitFieldIsEncoded();
    void aFieldWiderThanItsBitsIsRefused_data();
    void aFieldWiderThanItsBitsIsRefused();
};

// Status 00083037, config 1 802DC097, config 2 F7FF8064, worked out from tables 7-9 by hand.
void TstGeostarStatusWords::rqueryExampleDecodesToTheTableBits_data() {
    QTest::addColumn<QString>("word");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QVariant>("expected");
    auto row = [](const char *w, const char *k, QVariant v) {
        QTest::addRow("%s.%s", w, k) << QString(w) << QString(k) << v;
    };
    // 0x00083037: bits 19, 13, 12, 5, 4, 2, 1, 0.
    row("status", "jamming_detected", false);
    row("status", "flash_write_in_progress", false);
    row("status", "geopath_active", false);
    row("status", "state", "sleep"); // bit 23 = 0
    row("status", "solution_type", "autonomous");
    row("status", "solution_available", true); // bit 19
    row("status", "valid_since_start", false);
    row("status", "solution_dim", "3D");
    row("status", "date_from_nav_message", true); // bit 13
    row("status", "time_from_nav_message", true); // bit 12
    row("status", "almanac_gps", false);
    row("status", "almanac_glonass", false);
    row("status", "antenna", "not_measured"); // bits 7:6 = 0
    row("status", "agc_glonass_ok", true);    // bit 5
    row("status", "agc_gps_ok", true);        // bit 4
    row("status", "settings_loaded_from_flash", false);
    row("status", "pll_ok", true);        // bit 2
    row("status", "rtc_ok", true);        // bit 1
    row("status", "backup_ram_ok", true); // bit 0
    row("status", "reserved_bits", "00000000");
    // 0x802DC097: 31 (reserved), 21, 19, 18, 16 (reserved), 15, 14, 7, 4, 2, 1, 0.
    row("config1", "antenna_power", false);
    row("config1", "operating_mode", "autonomous_or_differential");
    row("config1", "raim", false);
    row("config1", "power_saving_enabled", false);
    row("config1", "power_saving_type", "RELAXED FIX");
    row("config1", "dynamics_code", 1);
    row("config1", "dynamics", "pedestrian_car");
    row("config1", "rate_code", 3);
    row("config1", "rate_hz", 1);
    row("config1", "kalman_filter", true);        // bit 15
    row("config1", "first_fix_2d_allowed", true); // bit 14
    row("config1", "mode_2d_allowed", false);
    row("config1", "geopath", false);
    row("config1", "pps_time_scale", "GPS");
    row("config1", "pps_polarity", "positive");
    row("config1", "pps_enabled", true); // bit 7
    row("config1", "search_unused_systems", false);
    row("config1", "sbas", true);    // bit 4
    row("config1", "qzss", false);   // bit 3
    row("config1", "galileo", true); // bit 2
    row("config1", "gps", true);     // bit 1
    row("config1", "glonass", true); // bit 0
    row("config1", "reserved_bits", "80010000");
    // 0xF7FF8064: type F7FF, bits 15 (datum 2), 6, 5 (reserved), 2.
    row("config2", "receiver_type_code", "F7FF");
    row("config2", "receiver_type", "GeoS-5M");
    row("config2", "datum_code", 2);
    row("config2", "datum", "user");
    row("config2", "differential_allowed", false);
    row("config2", "sbas_test_mode_allowed", false);
    row("config2", "use_all_satellites", false);
    row("config2", "sbas_prn", "auto"); // bit 2
    row("config2", "reserved_bits", "00000060");
}

void TstGeostarStatusWords::rqueryExampleDecodesToTheTableBits() {
    QFETCH(QString, word);
    QFETCH(QString, key);
    QFETCH(QVariant, expected);
    const QJsonObject o = exampleWord(qPrintable(word));
    QVERIFY2(o.contains(key), qPrintable(key));
    QCOMPARE(o[key].toVariant(), expected);
}

// One row per single-bit flag of tables 7-9: only that bit set → only that field true.
void TstGeostarStatusWords::eachSingleBitSetsItsNamedField_data() {
    QTest::addColumn<QString>("word");
    QTest::addColumn<int>("bit");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QVariant>("whenSet");
    QTest::addColumn<QVariant>("whenClear");
    auto row = [](const char *w, int b, const char *k, QVariant set = true,
                  QVariant clear = false) {
        QTest::addRow("%s bit %d %s", w, b, k) << QString(w) << b << QString(k) << set << clear;
    };
    row("status", 31, "jamming_detected");
    row("status", 30, "flash_write_in_progress");
    row("status", 28, "geopath_active");
    row("status", 27, "reference_within_threshold");
    row("status", 26, "averaging_in_progress");
    row("status", 25, "rtcm_corrections_used");
    row("status", 24, "sbas_corrections_used");
    row("status", 23, "state", "active", "sleep");
    row("status", 22, "solution_type", "differential", "autonomous");
    row("status", 21, "extrapolated");
    row("status", 20, "stationary");
    row("status", 19, "solution_available");
    row("status", 18, "valid_since_start");
    row("status", 16, "solution_dim", "2D", "3D");
    row("status", 15, "clock_restored_hot_start");
    row("status", 14, "gps_iono_utc_available");
    row("status", 13, "date_from_nav_message");
    row("status", 12, "time_from_nav_message");
    row("status", 11, "almanac_qzss");
    row("status", 10, "almanac_galileo");
    row("status", 9, "almanac_glonass");
    row("status", 8, "almanac_gps");
    row("status", 6, "antenna", "overloaded", "not_measured");
    row("status", 7, "antenna", "disconnected", "not_measured");
    row("status", 5, "agc_glonass_ok");
    row("status", 4, "agc_gps_ok");
    row("status", 3, "settings_loaded_from_flash");
    row("status", 2, "pll_ok");
    row("status", 1, "rtc_ok");
    row("status", 0, "backup_ram_ok");
    row("status", 29, "reserved_bits", "20000000", "00000000");
    row("status", 17, "reserved_bits", "00020000", "00000000");
    row("config1", 30, "antenna_power");
    row("config1", 28, "operating_mode", "fixed_coordinates", "autonomous_or_differential");
    row("config1", 27, "raim");
    row("config1", 26, "smoothed_pseudoranges");
    row("config1", 25, "power_saving_type", "FIX-BY-REQUEST", "RELAXED FIX");
    row("config1", 24, "power_saving_enabled");
    row("config1", 21, "dynamics", "pedestrian_car", "auto");
    row("config1", 22, "dynamics", "marine", "auto");
    row("config1", 23, "dynamics", "high_dynamics", "auto");
    row("config1", 18, "rate_hz", 5, 10);
    row("config1", 19, "rate_hz", 2, 10);
    row("config1", 15, "kalman_filter");
    row("config1", 14, "first_fix_2d_allowed");
    row("config1", 13, "mode_2d_allowed");
    row("config1", 12, "geopath");
    row("config1", 9, "pps_time_scale", "UTC", "GPS");
    row("config1", 10, "pps_time_scale", "GLONASS", "GPS");
    row("config1", 11, "pps_time_scale", "reserved", "GPS");
    row("config1", 8, "pps_polarity", "negative", "positive");
    row("config1", 7, "pps_enabled");
    row("config1", 6, "search_unused_systems");
    row("config1", 4, "sbas");
    row("config1", 3, "qzss");
    row("config1", 2, "galileo");
    row("config1", 1, "gps");
    row("config1", 0, "glonass");
    row("config1", 31, "reserved_bits", "80000000", "00000000");
    row("config1", 29, "reserved_bits", "20000000", "00000000");
    row("config1", 20, "reserved_bits", "00100000", "00000000");
    row("config1", 5, "reserved_bits", "00000020", "00000000");
    row("config2", 14, "datum", "PZ-90.11", "WGS-84");
    row("config2", 15, "datum", "user", "WGS-84");
    row("config2", 8, "differential_allowed");
    row("config2", 4, "sbas_test_mode_allowed");
    row("config2", 3, "use_all_satellites");
    row("config2", 2, "sbas_prn", "auto", "user");
    row("config2", 9, "reserved_bits", "00000200", "00000000");
    row("config2", 0, "reserved_bits", "00000001", "00000000");
}

void TstGeostarStatusWords::eachSingleBitSetsItsNamedField() {
    QFETCH(QString, word);
    QFETCH(int, bit);
    QFETCH(QString, key);
    QFETCH(QVariant, whenSet);
    QFETCH(QVariant, whenClear);
    const QByteArray w = word.toLatin1();
    QCOMPARE(wordJson(w.constData(), 1u << bit)[key].toVariant(), whenSet);
    QCOMPARE(wordJson(w.constData(), 0)[key].toVariant(), whenClear);
    // And the flag reads back from the raw word that is kept.
    QCOMPARE(wordJson(w.constData(), 1u << bit)["raw"].toString().toUInt(nullptr, 16), 1u << bit);
}

void TstGeostarStatusWords::receiverTypesOfTable9() {
    QCOMPARE(ConfigRegister2::decode(0xF7FF0000).receiverType(), std::string_view("GeoS-5M"));
    QCOMPARE(ConfigRegister2::decode(0xF7FE0000).receiverType(), std::string_view("GeoS-5MR"));
    QCOMPARE(ConfigRegister2::decode(0xF7FD0000).receiverType(), std::string_view("GeoS-5MH"));
    QCOMPARE(ConfigRegister2::decode(0xD7FE0000).receiverType(), std::string_view("GeoS-5MP"));
    QVERIFY(ConfigRegister2::decode(0x12340000).receiverType().empty());
    QVERIFY(wordJson("config2", 0x12340000)["receiver_type"].isNull());
    QCOMPARE(wordJson("config2", 0x12340000)["receiver_type_code"].toString(), QString("1234"));
}

void TstGeostarStatusWords::multiBitFieldsDecodeEveryValue() {
    const char *antenna[] = {"not_measured", "overloaded", "disconnected", "ok"};
    for (std::uint32_t v = 0; v < 4; ++v)
        QCOMPARE(wordJson("status", v << 6)["antenna"].toString(), QString(antenna[v]));
    const char *dyn[] = {"auto",          "pedestrian_car", "marine",    "airborne",
                         "high_dynamics", "undefined",      "undefined", "undefined"};
    for (std::uint32_t v = 0; v < 8; ++v)
        QCOMPARE(wordJson("config1", v << 21)["dynamics"].toString(), QString(dyn[v]));
    const int hz[] = {10, 5, 2, 1};
    for (std::uint32_t v = 0; v < 4; ++v)
        QCOMPARE(wordJson("config1", v << 18)["rate_hz"].toInt(), hz[v]);
    const char *pps[] = {"GPS", "UTC", "GLONASS", "UTC(SU)", "reserved"};
    for (std::uint32_t v = 0; v < 8; ++v)
        QCOMPARE(wordJson("config1", v << 9)["pps_time_scale"].toString(),
                 QString(pps[std::min<std::uint32_t>(v, 4)]));
    const char *datum[] = {"WGS-84", "PZ-90.11", "user", "undefined"};
    for (std::uint32_t v = 0; v < 4; ++v)
        QCOMPARE(wordJson("config2", v << 14)["datum"].toString(), QString(datum[v]));
}

// The spec example's words, every single bit of each table (reserved ones too), none and all.
void TstGeostarStatusWords::encodeIsTheInverseOfDecode_data() {
    QTest::addColumn<QString>("word");
    QTest::addColumn<uint>("value");
    QTest::addRow("status example") << "status" << 0x00083037u;
    QTest::addRow("config1 example") << "config1" << 0x802DC097u;
    QTest::addRow("config2 example") << "config2" << 0xF7FF8064u;
    // The row names made as text (a "%s" of the loop's pointer made GCC's Release build warn that
    // it might be null).
    for (const QString w : {"status", "config1", "config2"}) {
        QTest::newRow(qPrintable(w + " none")) << w << 0u;
        QTest::newRow(qPrintable(w + " all")) << w << 0xFFFFFFFFu;
        for (int b = 0; b < 32; ++b)
            QTest::newRow(qPrintable(QStringLiteral("%1 bit %2").arg(w).arg(b))) << w << (1u << b);
    }
}

void TstGeostarStatusWords::encodeIsTheInverseOfDecode() {
    QFETCH(QString, word);
    QFETCH(uint, value);
    const EncodedWord e = reencoded(word, value, true);
    QVERIFY2(e.ok(), e.refusal.text.c_str());
    QCOMPARE(uint(e.word), value);
}

void TstGeostarStatusWords::theFieldsAloneGiveEveryBitButTheReservedOnes_data() {
    encodeIsTheInverseOfDecode_data();
}

void TstGeostarStatusWords::theFieldsAloneGiveEveryBitButTheReservedOnes() {
    QFETCH(QString, word);
    QFETCH(uint, value);
    const EncodedWord e = reencoded(word, value, false);
    QVERIFY2(e.ok(), e.refusal.text.c_str());
    QCOMPARE(uint(e.word), value & ~reservedMask(word));
}

void TstGeostarStatusWords::everyValueOfAMultiBitFieldIsEncoded() {
    for (int v = 0; v < 4; ++v) {
        StatusWord s;
        s.antenna = static_cast<AntennaState>(v);
        QCOMPARE(s.encode().word, std::uint32_t(v) << 6);
    }
    for (int v = 0; v < 8; ++v) {
        ConfigRegister1 c;
        c.dynamicsCode = v;
        c.ppsTimeScaleCode = 7 - v;
        QCOMPARE(c.encode().word, (std::uint32_t(v) << 21) | (std::uint32_t(7 - v) << 9));
    }
    for (int hz : {10, 5, 2, 1}) {
        ConfigRegister1 c;
        c.rateCode = rateHzToCode(hz);
        QCOMPARE(ConfigRegister1::decode(c.encode().word).rateHz, hz);
    }
    QCOMPARE(rateHzToCode(3), -1);
    for (int v = 0; v < 4; ++v) {
        ConfigRegister2 c;
        c.receiverTypeCode = 0xD7FE;
        c.datumCode = v;
        QCOMPARE(c.encode().word, 0xD7FE0000u | (std::uint32_t(v) << 14));
    }
}

// A code that does not fit its bits would spill into the next field: refused, naming the field.
void TstGeostarStatusWords::aFieldWiderThanItsBitsIsRefused_data() {
    QTest::addColumn<QString>("word");
    QTest::addColumn<QString>("field");
    QTest::addColumn<int>("value");
    QTest::addColumn<QString>("accepted");
    const auto row = [](const char *name, const char *w, const char *f, int v, const char *a) {
        QTest::newRow(name) << QString(w) << QString(f) << v << QString(a);
    };
    row("antenna 4", "status", "antenna", 4, "0..3");
    row("dynamics 8", "config1", "dynamics", 8, "0..7");
    row("dynamics -1", "config1", "dynamics", -1, "0..7");
    row("rate code 4", "config1", "rate", 4, "0..3");
    row("rate code -1 (no such rate)", "config1", "rate", -1, "0..3");
    row("1PPS time scale 8", "config1", "1PPS", 8, "0..7");
    row("datum 4", "config2", "datum", 4, "0..3");
}

void TstGeostarStatusWords::aFieldWiderThanItsBitsIsRefused() {
    QFETCH(QString, word);
    QFETCH(QString, field);
    QFETCH(int, value);
    QFETCH(QString, accepted);
    EncodedWord e;
    if (word == "status") {
        StatusWord s;
        s.antenna = static_cast<AntennaState>(value);
        e = s.encode();
    } else if (word == "config1") {
        ConfigRegister1 c;
        if (field == "dynamics") c.dynamicsCode = value;
        if (field == "rate") c.rateCode = value;
        if (field == "1PPS") c.ppsTimeScaleCode = value;
        e = c.encode();
    } else {
        ConfigRegister2 c;
        c.datumCode = value;
        e = c.encode();
    }
    QVERIFY(!e.ok());
    QCOMPARE(e.word, 0u);
    const QString text = QString::fromStdString(e.refusal.text);
    QVERIFY2(text.contains(field) && text.contains(QString::number(value)) &&
                     text.endsWith("accepted: " + accepted),
             qPrintable(text));
    QVERIFY(e.refusal.form); // a translatable template
}

QTEST_APPLESS_MAIN(TstGeostarStatusWords)
#include "tst_geostar_status_words.moc"
