// PNMRX300-303 navigation data in engineering units. The test carries its own copy of the
// IS-GPS-200 widths and scale factors (tables 20-I, 20-III, 20-VI; 20.3.3.5.1.6/7), builds the
// hex itself, and checks the decoders against it: every field, positive and negative (sign
// extension from the field's own bit width, and from a wider sign-extended word), then a
// realistic ephemeris with known values, the three-message assembly, and the almanac upload.
#include "decode_helper.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_ephemeris.h"

#include <QJsonArray>
#include <QTest>

#include <cmath>
#include <vector>

using gnss::test::decodeOne;

namespace {

struct Field {
    const char *key;
    int bits;
    bool isSigned;
    int scale;
};

// IS-GPS-200 (not the Nemerix table, whose errors docs/spec-notes.md lists).
const std::vector<Field> kSf1 = {
        {"week", 10, false, 0}, {"health", 6, false, 0}, {"ura", 4, false, 0},
        {"tgd", 8, true, -31},  {"iodc", 10, false, 0},  {"toc", 16, false, 4},
        {"af2", 8, true, -55},  {"af1", 16, true, -43},  {"af0", 22, true, -31}};
const std::vector<Field> kSf2 = {
        {"iode", 8, false, 0},  {"crs", 16, true, -5},      {"delta_n", 16, true, -43},
        {"m0", 32, true, -31},  {"cuc", 16, true, -29},     {"e", 32, false, -33},
        {"cus", 16, true, -29}, {"sqrt_a", 32, false, -19}, {"toe", 16, false, 4}};
const std::vector<Field> kSf3 = {
        {"cic", 16, true, -29},       {"omega0", 32, true, -31}, {"cis", 16, true, -29},
        {"i0", 32, true, -31},        {"crc", 16, true, -5},     {"omega", 32, true, -31},
        {"omega_dot", 24, true, -43}, {"iode", 8, false, 0},     {"idot", 14, true, -43}};
const std::vector<Field> kAlmanac = {
        {"e", 16, false, -21},      {"health", 8, false, 0},      {"toa", 8, false, 12},
        {"delta_i", 16, true, -19}, {"omega_dot", 16, true, -38}, {"sqrt_a", 24, false, -11},
        {"omega0", 24, true, -23},  {"perigee", 24, true, -23},   {"mean", 24, true, -23},
        {"m0", 24, true, -23},      {"af0", 11, true, -20},       {"af1", 11, true, -38}};
const std::vector<Field> kIono = {{"alpha0", 8, true, -30}, {"alpha1", 8, true, -27},
                                  {"alpha2", 8, true, -24}, {"alpha3", 8, true, -24},
                                  {"beta0", 8, true, 11},   {"beta1", 8, true, 14},
                                  {"beta2", 8, true, 16},   {"beta3", 8, true, 16}};
const std::vector<Field> kUtc = {{"a0", 32, true, -30},        {"a1", 24, true, -50},
                                 {"dt_ls", 8, true, 0},        {"tot", 8, false, 12},
                                 {"wn_t", 8, false, 0},        {"wn_lsf", 8, false, 0},
                                 {"dn", 8, false, 0},          {"dt_lsf", 8, true, 0},
                                 {"num_blocks", 32, false, 0}, {"time_offset", 32, false, 0}};

// Two's complement of v in `bits` bits, upper-case hex, ceil(bits/4) digits.
QString twos(qint64 v, int bits) {
    const quint64 mask = (bits >= 64) ? ~0ULL : ((1ULL << bits) - 1);
    return QString("%1")
            .arg(static_cast<quint64>(v) & mask, (bits + 3) / 4, 16, QChar('0'))
            .toUpper();
}

QString sentence(const QString &head, const std::vector<Field> &fields, int target, qint64 raw) {
    QString s = head;
    for (int i = 0; i < static_cast<int>(fields.size()); ++i)
        s += "," + twos(i == target ? raw : 0, fields[i].bits);
    return s;
}

gnss::DecoderOptions nemerix() {
    gnss::DecoderOptions o;
    o.dialect = "nemerix";
    return o;
}

// The assembler takes typed messages: decode a line into one.
template <class T> std::optional<T> decodeTyped(const std::string &line) {
    static const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    gnss::StreamDecoder dec(registry, nemerix());
    std::optional<T> out;
    dec.decodeLine(line, [&](const gnss::SentenceEvent &ev) {
        if (ev.message)
            if (const T *m = gnss::message_cast<T>(*ev.message)) out = *m;
    });
    return out;
}

} // namespace

class TstNemerixNavData : public QObject {
    Q_OBJECT
private slots:
    void everyFieldIsScaledAndSignExtended_data();
    void everyFieldIsScaledAndSignExtended();
    void wordAlreadySignExtendedIsAccepted();
    void valueWiderThanItsFieldIsRefused();
    void ephemerisWithKnownValuesDecodesToThem();
    void ephemerisAssembledOnceAllThreeSubframesArrived();
    void ephemerisWithMismatchedIssueOfDataWaits();
    void almanacUploadRoundTrips();
    void almanacWithoutTheDuplicatedMeanFieldDecodes();
    void almanacUploadRefusesBadValues();
};

void TstNemerixNavData::everyFieldIsScaledAndSignExtended_data() {
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("key");
    QTest::addColumn<qint64>("raw");
    QTest::addColumn<int>("bits");
    QTest::addColumn<int>("scale");
    auto add = [](const char *what, const QString &head, const std::vector<Field> &fields) {
        for (int i = 0; i < static_cast<int>(fields.size()); ++i) {
            const Field &f = fields[i];
            const qint64 maxPos = f.isSigned ? (1LL << (f.bits - 1)) - 1 : (1LL << f.bits) - 1;
            std::vector<qint64> raws = {1, maxPos};
            if (f.isSigned) raws.push_back(-(1LL << (f.bits - 1))), raws.push_back(-3);
            for (qint64 raw : raws)
                QTest::addRow("%s %s %lld", what, f.key, static_cast<long long>(raw))
                        << sentence(head, fields, i, raw) << QString(f.key) << raw << f.bits
                        << f.scale;
        }
    };
    add("sf1", "$PNMRX301,7,1", kSf1);
    add("sf2", "$PNMRX301,7,2", kSf2);
    add("sf3", "$PNMRX301,7,3", kSf3);
    add("almanac", "$PNMRX300,7", kAlmanac);
    add("iono", "$PNMRX302,7", kIono);
    add("utc", "$PNMRX303,7", kUtc);
}

void TstNemerixNavData::everyFieldIsScaledAndSignExtended() {
    QFETCH(QString, line);
    QFETCH(QString, key);
    QFETCH(qint64, raw);
    QFETCH(int, bits);
    QFETCH(int, scale);
    const auto d = decodeOne(line, nemerix());
    QVERIFY2(d.ok, qPrintable(line + ": " + d.error));
    QCOMPARE(d.data[key + "_raw"].toString(), twos(raw, bits));
    QCOMPARE(d.data[key].toDouble(), std::ldexp(static_cast<double>(raw), scale));
}

void TstNemerixNavData::wordAlreadySignExtendedIsAccepted() {
    // af0 (22-bit) = -5 printed as a sign-extended 32-bit word, and in lower case.
    QString line = sentence("$PNMRX301,3,1", kSf1, -1, 0);
    line.replace(line.lastIndexOf(",") + 1, 6, "fffffffb");
    const auto d = decodeOne(line, nemerix());
    QVERIFY2(d.ok, qPrintable(line + ": " + d.error));
    QCOMPARE(d.data["af0"].toDouble(), std::ldexp(-5.0, -31));
    QCOMPARE(d.data["af0_raw"].toString(), QString("3FFFFB"));
}

void TstNemerixNavData::valueWiderThanItsFieldIsRefused() {
    // toc is 16-bit unsigned: 0x1FFFF does not fit; af2 is 8-bit: 0x0180 neither.
    QString line = "$PNMRX301,3,1,000,00,0,00,000,1FFFF,00,0000,000000";
    QVERIFY(!decodeOne(line, nemerix()).ok);
    line = "$PNMRX301,3,1,000,00,0,00,000,0000,0180,0000,000000";
    const auto d = decodeOne(line, nemerix());
    QVERIFY(!d.ok);
    QVERIFY2(d.error.contains("af2"), qPrintable(d.error));
}

void TstNemerixNavData::ephemerisWithKnownValuesDecodesToThem() {
    // A plausible GPS ephemeris; each value is encoded here with the IS-GPS-200 scale.
    struct Known {
        const std::vector<Field> *sf;
        const char *key;
        double value;
    };
    const Known known[] = {
            {&kSf1, "week", 123},
            {&kSf1, "tgd", -1.117587e-8},
            {&kSf1, "iodc", 0x1A5},
            {&kSf1, "toc", 302400},
            {&kSf1, "af0", -1.2345e-5},
            {&kSf1, "af1", -2.273737e-12},
            {&kSf1, "af2", 0},
            {&kSf2, "iode", 0xA5},
            {&kSf2, "crs", -62.375},
            {&kSf2, "delta_n", 1.4e-9},
            {&kSf2, "m0", -0.6732},
            {&kSf2, "cuc", -3.2e-6},
            {&kSf2, "e", 0.0123},
            {&kSf2, "cus", 7.5e-6},
            {&kSf2, "sqrt_a", 5153.65},
            {&kSf2, "toe", 302400},
            {&kSf3, "cic", 1.1e-7},
            {&kSf3, "omega0", -0.2871},
            {&kSf3, "cis", -5.6e-8},
            {&kSf3, "i0", 0.3064},
            {&kSf3, "crc", 227.4},
            {&kSf3, "omega", 0.8123},
            {&kSf3, "omega_dot", -2.6e-9},
            {&kSf3, "iode", 0xA5},
            {&kSf3, "idot", -1.1e-10},
    };
    QString lines[3];
    const std::vector<Field> *sfs[3] = {&kSf1, &kSf2, &kSf3};
    for (int k = 0; k < 3; ++k) {
        lines[k] = QString("$PNMRX301,12,%1").arg(k + 1);
        for (const Field &f : *sfs[k]) {
            double v = 0;
            for (const auto &kn : known)
                if (kn.sf == sfs[k] && QString(kn.key) == f.key) v = kn.value;
            lines[k] += "," + twos(std::llround(std::ldexp(v, -f.scale)), f.bits);
        }
    }
    for (int k = 0; k < 3; ++k) {
        const auto d = decodeOne(lines[k], nemerix());
        QVERIFY2(d.ok, qPrintable(d.error));
        for (const auto &kn : known) {
            if (kn.sf != sfs[k]) continue;
            int scale = 0;
            for (const Field &f : *kn.sf)
                if (QString(f.key) == kn.key) scale = f.scale;
            const double halfLsb = std::ldexp(0.5, scale) * 1.000001;
            QVERIFY2(std::fabs(d.data[kn.key].toDouble() - kn.value) <= halfLsb,
                     qPrintable(QString("%1: %2 vs %3")
                                        .arg(kn.key)
                                        .arg(d.data[kn.key].toDouble())
                                        .arg(kn.value)));
        }
    }
    // The assembled ephemeris gives the same values.
    gnss::nemerix::EphemerisAssembler a;
    std::optional<gnss::nemerix::Ephemeris> eph;
    for (const auto &l : lines) {
        auto part = decodeTyped<gnss::nemerix::EphemerisSubframe>(l.toStdString());
        QVERIFY(part);
        eph = a.add(*part);
    }
    QVERIFY(eph);
    using S = gnss::nemerix::EphemerisSubframe;
    QVERIFY(std::fabs(eph->value(2, S::SqrtA) - 5153.65) < std::ldexp(1.0, -19));
    QVERIFY(std::fabs(eph->value(2, S::Ecc) - 0.0123) < std::ldexp(1.0, -33));
    QVERIFY(std::fabs(eph->value(3, S::I0) - 0.3064) < std::ldexp(1.0, -31));
    QCOMPARE(eph->value(1, S::Toc), 302400.0);
    QVERIFY(eph->consistent());
}

void TstNemerixNavData::ephemerisAssembledOnceAllThreeSubframesArrived() {
    using namespace gnss::nemerix;
    auto part = [](int sv, int sf, int iod) {
        EphemerisSubframe p;
        p.sv = sv;
        p.subframe = sf;
        for (auto &r : p.raw) r = 0;
        if (sf == 1) p.raw[EphemerisSubframe::Iodc] = iod;
        if (sf == 2) p.raw[EphemerisSubframe::Iode2] = iod & 0xFF;
        if (sf == 3) p.raw[EphemerisSubframe::Iode3] = iod & 0xFF;
        return p;
    };
    EphemerisAssembler a;
    // Out of order, interleaved with another satellite.
    QVERIFY(!a.add(part(4, 3, 0x120)));
    QVERIFY(!a.add(part(9, 1, 7)));
    QVERIFY(!a.add(part(4, 1, 0x120)));
    QCOMPARE(a.pendingMask(4), 5);
    QVERIFY(!a.add(part(9, 2, 7)));
    const auto four = a.add(part(4, 2, 0x120));
    QVERIFY(four);
    QCOMPARE(four->sv, 4);
    QCOMPARE(a.pendingMask(4), 0);
    const auto nine = a.add(part(9, 3, 7));
    QVERIFY(nine);
    QCOMPARE(nine->sv, 9);
    // The JSON of the assembled ephemeris has every field once (iode of subframe 3 as iode3).
    std::string json;
    gnss::JsonWriter w(json);
    nine->writeJson(w);
    QVERIFY(json.find("\"iode3\":7") != std::string::npos);
    QVERIFY(json.find("\"consistent\":true") != std::string::npos);
    QVERIFY(!a.add(part(0, 1, 1)));
    QVERIFY(!a.add(part(33, 1, 1)));
}

void TstNemerixNavData::ephemerisWithMismatchedIssueOfDataWaits() {
    using namespace gnss::nemerix;
    auto part = [](int sf, int iod) {
        EphemerisSubframe p;
        p.sv = 2;
        p.subframe = sf;
        for (auto &r : p.raw) r = 0;
        if (sf == 1) p.raw[EphemerisSubframe::Iodc] = iod;
        if (sf == 2) p.raw[EphemerisSubframe::Iode2] = iod;
        if (sf == 3) p.raw[EphemerisSubframe::Iode3] = iod;
        return p;
    };
    EphemerisAssembler a;
    QVERIFY(!a.add(part(1, 10)));
    QVERIFY(!a.add(part(2, 10)));
    QVERIFY(!a.add(part(3, 11))); // stale: waits for the matching subframe 3
    QVERIFY(a.add(part(3, 10)));
}

void TstNemerixNavData::almanacUploadRoundTrips() {
    using namespace gnss::nemerix;
    Almanac a;
    a.sv = 17;
    const qint64 raws[] = {0x2A1F,    0x00,     0x90,      -0x0C4B,   -0x00A5, 0xA10D3A,
                           -0x3A1B2C, 0x11F00E, -0x123456, -0x123456, -3,      0x3FF};
    for (int f = 0; f < Almanac::kFieldCount; ++f) a.raw[f] = raws[f];
    const auto r = encodeAlmanac(a);
    QVERIFY2(r.ok(), r.error.c_str());
    QCOMPARE(r.sentences.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(r.sentences[0]),
             QString("$PNMRX300,17,2A1F,00,90,F3B5,FF5B,A10D3A,C5E4D4,11F00E,EDCBAA,EDCBAA,7FD,"
                     "3FF*") +
                     QString::asprintf("%02X", gnss::nmeaChecksum(r.sentences[0].substr(
                                                       1, r.sentences[0].size() - 4))));
    const auto d = decodeOne(QString::fromStdString(r.sentences[0]), nemerix());
    QVERIFY2(d.ok, qPrintable(d.error));
    QCOMPARE(d.checksum, QString("ok"));
    QCOMPARE(d.data["sv"].toInt(), 17);
    for (int f = 0; f < Almanac::kFieldCount; ++f) {
        const Field &def = kAlmanac[f];
        QCOMPARE(d.data[def.key].toDouble(), std::ldexp(static_cast<double>(raws[f]), def.scale));
    }
    QCOMPARE(d.data["toa"].toDouble(), 0x90 * 4096.0);
    QCOMPARE(d.data["af0"].toDouble(), -3.0 / (1 << 20));
    QCOMPARE(d.data["inclination"].toDouble(), 0.30 + std::ldexp(-0x0C4B, -19));
    // Renamed prefix on upload.
    const auto renamed = encodeAlmanac(a, "PXYZW");
    QVERIFY(renamed.ok());
    QCOMPARE(renamed.sentences[0].substr(0, 9), std::string("$PXYZW300"));
    QCOMPARE(QString::fromStdString(applyPrefix(r.sentences[0], "PXYZW")),
             QString::fromStdString(renamed.sentences[0]));
}

void TstNemerixNavData::almanacWithoutTheDuplicatedMeanFieldDecodes() {
    // 11 hex fields: the IS-GPS-200 set, without the table's extra "Mean".
    const auto d = decodeOne("$PNMRX300,3,2A1F,00,90,F3B5,FF5B,A10D3A,C5E4D4,11F00E,EDCBAA,7FD,3FF",
                             nemerix());
    QVERIFY2(d.ok, qPrintable(d.error));
    QVERIFY(d.data["mean"].isNull());
    QCOMPARE(d.data["m0_raw"].toString(), QString("EDCBAA"));
    QCOMPARE(d.data["af1"].toDouble(), std::ldexp(1023.0, -38));
    QVERIFY(!decodeOne("$PNMRX300,3,2A1F,00,90", nemerix()).ok);
}

void TstNemerixNavData::almanacUploadRefusesBadValues() {
    using namespace gnss::nemerix;
    Almanac a;
    a.sv = 33;
    for (auto &r : a.raw) r = 0;
    auto r = encodeAlmanac(a);
    QVERIFY(!r.ok());
    QVERIFY(r.sentences.empty());
    QVERIFY2(r.error.find("1..32") != std::string::npos, r.error.c_str());
    a.sv = 1;
    a.raw[Almanac::Af0] = 1024; // 11-bit signed: max 1023
    r = encodeAlmanac(a);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.find("af0") != std::string::npos, r.error.c_str());
    a.raw[Almanac::Af0] = 0;
    a.raw[Almanac::SqrtA] = std::nullopt;
    r = encodeAlmanac(a);
    QVERIFY2(r.error.find("sqrt_a") != std::string::npos, r.error.c_str());
    // From engineering units with the library's own conversion.
    std::string err;
    QVERIFY(!toRaw(1.0, Almanac::fields()[Almanac::Af0], err));
    QVERIFY2(err.find("af0") != std::string::npos, err.c_str());
    QCOMPARE(*toRaw(-3.0 / (1 << 20), Almanac::fields()[Almanac::Af0], err), qint64(-3));
}

QTEST_APPLESS_MAIN(TstNemerixNavData)
#include "tst_nemerix_navdata.moc"
