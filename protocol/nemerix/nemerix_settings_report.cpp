// PNMRX603: settings report (and, without fields, its request).
//
//   $PNMRX603*6C      request (the spec prints *00, which is not its checksum)
//   $PNMRX603,0,s1..s7,d1..d7,nmrx,uart*hh
//       7 message sequence values, 7 message delays (per NMEA message; the order GGA GLL GSA
//       GSV RMC VTG ZDA of the PNMRX103 table is an inference), Nemerix messages enabled and
//       UART settings: 32-bit hex words whose bit layout the spec does not give (kept raw)
//   $PNMRX603,1,a0,a1,a2,a3,b0,b1,b2,b3,valid,blocks,tzh,tzm*hh
//       ionospheric coefficients (hex, PNMRX302 scales), valid flag, 20-year blocks, time zone
//   $PNMRX603,2,maxpdop,maxhdop,invalidsv,mincno,minelev,maxtm,maxsv*hh
//   $PNMRX603,3,acq1,acq2,noisefloor,kalman,altitude*hh
//   $PNMRX603,4,corr,datum,dx,dy,dz,iflat,majora*hh     as in PNMRX106
//
// encodeSettingsReport writes one message as the receiver sends it: integers in decimal, the
// floats of message 2 with one decimal ("10.0", DOPs being set in tenths), hex words of 8 digits
// and the one-digit hex fields (valid, blocks, Kalman mode) of one; each value within the width
// the spec's table gives its field. The spec prints no example of a report.
#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_fields.h"

#include <cmath>

namespace gnss::nemerix {

const MessageType SettingsReport::kType{"PNMRX603"};
const MessageType PlainCommand::kSettingsQueryType{"PNMRX603 request"};

namespace {
const HexFieldDef kWord{"word", 32, false, 0, ""};
} // namespace

bool decodeSettingsReport(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    if (usedFields(r) == 0) {
        PlainCommand m(PlainCommand::kSettingsQueryType);
        return finishDecode(r, ctx, m);
    }
    SettingsReport m;
    const auto nb = r.integer(0, "message number");
    if (!nb || *nb < 0 || *nb > 4) {
        if (r.ok()) r.fail(0, "message number", QT_TRANSLATE_NOOP("Refusal", "not 0..4"));
        return finishDecode(r, ctx, m);
    }
    m.number = *nb;
    auto word = [&](std::size_t i, const char *name) -> std::optional<std::uint64_t> {
        HexFieldDef d = kWord;
        d.key = name;
        const auto v = readHex(r, i, d);
        return v ? std::optional<std::uint64_t>(static_cast<std::uint64_t>(*v)) : std::nullopt;
    };
    switch (m.number) {
    case 0:
        r.require(17);
        for (std::size_t i = 0; i < 7; ++i) {
            m.sequence[i] = r.integer(1 + i, "message sequence");
            m.delay[i] = r.integer(8 + i, "message delay");
        }
        m.nmrxEnabled = word(15, "nmrx_enabled");
        m.uartSettings = word(16, "uart_settings");
        break;
    case 1: {
        r.require(13);
        const auto iono = Ionosphere::fields();
        for (std::size_t i = 0; i < 8; ++i) m.iono[i] = readHex(r, 1 + i, iono[i]);
        m.ionoValid = word(9, "iono_valid");
        m.numBlocks = word(10, "num_blocks");
        m.tzHours = r.integer(11, "local zone hours");
        m.tzMinutes = r.integer(12, "local zone minutes");
        if (m.tzHours && (*m.tzHours < -13 || *m.tzHours > 13))
            r.fail(11, "local zone hours", QT_TRANSLATE_NOOP("Refusal", "out of range -13..13"));
        if (m.tzMinutes && (*m.tzMinutes < -59 || *m.tzMinutes > 59))
            r.fail(12, "local zone minutes", QT_TRANSLATE_NOOP("Refusal", "out of range -59..59"));
        break;
    }
    case 2:
        r.require(8);
        m.maxPdop = r.real(1, "max PDOP");
        m.maxHdop = r.real(2, "max HDOP");
        m.invalidSv = word(3, "invalid_sv");
        m.minCno = r.real(4, "min CNO");
        m.minElevation = r.real(5, "min elevation");
        m.maxTm = r.integer(6, "max TM");
        m.maxSvForFix = r.integer(7, "max SV for fix");
        break;
    case 3:
        r.require(6);
        m.acqThreshold1 = r.integer64(1, "acquisition threshold 1");
        m.acqThreshold2 = r.integer64(2, "acquisition threshold 2");
        m.noiseFloor = r.integer64(3, "noise floor");
        m.kalmanMode = word(4, "kalman_mode");
        m.defaultAltitude = r.integer64(5, "default altitude");
        break;
    case 4:
        r.require(8);
        m.correction = r.integer(1, "correction mode");
        m.datum = r.integer(2, "map datum");
        m.dx = r.integer64(3, "dx");
        m.dy = r.integer64(4, "dy");
        m.dz = r.integer64(5, "dz");
        m.iflatRaw = r.integer64(6, "inverse flatness");
        m.majorARaw = r.integer64(7, "major axis");
        break;
    }
    return finishDecode(r, ctx, m);
}

namespace {
void writeWord(JsonWriter &w, std::string_view key, const std::optional<std::uint64_t> &v) {
    w.key(key);
    if (v)
        w.value(formatHex(static_cast<std::int64_t>(*v), 32));
    else
        w.null();
}
} // namespace

// ---- Encoding -------------------------------------------------------------------------------

std::uint64_t nmrxEnabledWord(std::span<const int, 5> modes) {
    std::uint64_t w = 0;
    for (std::size_t i = 0; i < modes.size(); ++i)
        w |= static_cast<std::uint64_t>(modes[i] & 3) << (2 * i);
    return w;
}

std::uint64_t uartSettingsWord(int baud, int parity, int protocol) {
    return (static_cast<std::uint64_t>(baud) & 0xFFFFF) |
           ((static_cast<std::uint64_t>(parity) & 0xF) << 20) |
           ((static_cast<std::uint64_t>(protocol) & 0xFF) << 24);
}

namespace {

Refusal outOfRange(const char *name, const std::string &given, const std::string &accepted) {
    return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                   {name, given, accepted});
}

// Builds the fields of one message, refusing the first value that is missing or too wide.
class ReportFields {
public:
    // An integer of at most `chars` characters (a sign counts); with lo/hi, also within them.
    template <class T>
    void integer(const std::optional<T> &v, const char *name, int chars,
                 std::optional<long long> lo = {}, std::optional<long long> hi = {}) {
        if (!need(v.has_value(), name)) return;
        long long max = 1, min;
        for (int i = 0; i < chars; ++i) max *= 10;
        min = -(max / 10 - 1);
        --max;
        if (lo) min = std::max(min, *lo);
        if (hi) max = std::min(max, *hi);
        const long long x = static_cast<long long>(*v);
        if (x < min || x > max)
            return fail(outOfRange(name, std::to_string(x),
                                   std::to_string(min) + ".." + std::to_string(max)));
        text_ += "," + std::to_string(x);
    }
    // A hex word of `bits` (8 digits for 32, one for 4).
    void word(const std::optional<std::uint64_t> &v, const char *name, int bits) {
        if (!need(v.has_value(), name)) return;
        const std::uint64_t max = (1ULL << bits) - 1;
        if (*v > max)
            return fail(outOfRange(name, std::to_string(*v), "0.." + std::to_string(max)));
        text_ += "," + formatHex(static_cast<std::int64_t>(*v), bits);
    }
    // A raw word of a PNMRX302 field (message 1's coefficients).
    void hex(const std::optional<std::int64_t> &v, const HexFieldDef &def) {
        if (!ok()) return;
        if (Refusal why = checkRaw(v, def); !why.empty()) return fail(std::move(why));
        text_ += "," + formatHex(*v, def.bits);
    }
    // A float with one decimal.
    void real(const std::optional<double> &v, const char *name) {
        if (!need(v.has_value(), name)) return;
        if (!std::isfinite(*v) || *v < 0 || *v > 999.9)
            return fail(outOfRange(name, formatFixed(*v, 3), "0..999.9"));
        text_ += "," + formatFixed(*v, 1);
    }
    bool ok() const { return why_.empty(); }
    Refusal take() { return std::move(why_); }
    const std::string &text() const { return text_; }

private:
    bool need(bool present, const char *name) {
        if (!ok()) return false;
        if (!present) fail(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: missing"), {name}));
        return ok();
    }
    void fail(Refusal why) { why_ = std::move(why); }
    std::string text_;
    Refusal why_;
};

} // namespace

EncodeResult encodeSettingsReport(const SettingsReport &m, std::string_view prefix) {
    EncodeResult r;
    if (m.number < 0 || m.number > 4) {
        r.refuse(outOfRange("message number", std::to_string(m.number), "0..4"));
        return r;
    }
    ReportFields f;
    f.integer(std::optional<int>(m.number), "message number", 1);
    switch (m.number) {
    case 0:
        for (const auto &v : m.sequence) f.integer(v, "message sequence", 1, 0);
        for (const auto &v : m.delay) f.integer(v, "message delay", 1, 0);
        f.word(m.nmrxEnabled, "nmrx_enabled", 32);
        f.word(m.uartSettings, "uart_settings", 32);
        break;
    case 1: {
        const auto iono = Ionosphere::fields();
        for (std::size_t i = 0; i < iono.size(); ++i) f.hex(m.iono[i], iono[i]);
        f.word(m.ionoValid, "iono_valid", 4);
        f.word(m.numBlocks, "num_blocks", 4);
        f.integer(m.tzHours, "local zone hours", 3, -13, 13);
        f.integer(m.tzMinutes, "local zone minutes", 3, -59, 59);
        break;
    }
    case 2:
        f.real(m.maxPdop, "max PDOP");
        f.real(m.maxHdop, "max HDOP");
        f.word(m.invalidSv, "invalid_sv", 32);
        f.real(m.minCno, "min CNO");
        f.real(m.minElevation, "min elevation");
        f.integer(m.maxTm, "max TM", 2, 0);
        f.integer(m.maxSvForFix, "max SV for fix", 2, 0);
        break;
    case 3:
        f.integer(m.acqThreshold1, "acquisition threshold 1", 8);
        f.integer(m.acqThreshold2, "acquisition threshold 2", 8);
        f.integer(m.noiseFloor, "noise floor", 8);
        f.word(m.kalmanMode, "kalman_mode", 4);
        f.integer(m.defaultAltitude, "default altitude", 8);
        break;
    case 4:
        f.integer(m.correction, "correction mode", 1, 0);
        f.integer(m.datum, "map datum", 8, 0);
        f.integer(m.dx, "dx", 8);
        f.integer(m.dy, "dy", 8);
        f.integer(m.dz, "dz", 8);
        f.integer(m.iflatRaw, "inverse flatness", 8);
        f.integer(m.majorARaw, "major axis", 8);
        break;
    }
    if (!f.ok()) {
        r.refuse(f.take());
        return r;
    }
    return buildCommand("603", f.text(), prefix);
}

void SettingsReport::writeJson(JsonWriter &w) const {
    w.beginObject().field("message", number);
    switch (number) {
    case 0: {
        w.key("sequence").beginArray();
        for (const auto &v : sequence) w.value(v);
        w.endArray().key("delay_s").beginObject();
        for (std::size_t i = 0; i < kNmeaMessageIds.size(); ++i)
            w.field(kNmeaMessageIds[i], delay[i]);
        w.endObject();
        writeWord(w, "nmrx_enabled", nmrxEnabled);
        writeWord(w, "uart_settings", uartSettings);
        break;
    }
    case 1:
        writeHexFields(w, Ionosphere::fields(), iono);
        w.field("iono_valid", ionoValid)
                .field("num_blocks", numBlocks)
                .field("tz_hours", tzHours)
                .field("tz_minutes", tzMinutes);
        break;
    case 2:
        w.field("max_pdop", maxPdop).field("max_hdop", maxHdop);
        writeWord(w, "invalid_sv", invalidSv);
        w.key("excluded_svs").beginArray();
        if (invalidSv)
            for (int b = 0; b < 32; ++b)
                if (*invalidSv & (1ULL << b)) w.value(b + 1);
        w.endArray()
                .field("min_cno", minCno)
                .field("min_elevation", minElevation)
                .field("max_tm", maxTm)
                .field("max_sv_for_fix", maxSvForFix);
        break;
    case 3:
        w.field("acq_threshold_1", acqThreshold1)
                .field("acq_threshold_2", acqThreshold2)
                .field("noise_floor", noiseFloor)
                .field("kalman_mode", kalmanMode)
                .field("default_altitude", defaultAltitude);
        break;
    case 4: {
        w.field("correction", correction)
                .field("datum", datum)
                .field("dx", dx)
                .field("dy", dy)
                .field("dz", dz)
                .field("iflat_raw", iflatRaw)
                .field("major_axis_raw", majorARaw);
        w.key("inverse_flattening");
        if (iflatRaw)
            w.value(290.0 + static_cast<double>(*iflatRaw) / 1e6);
        else
            w.null();
        w.key("semi_major_axis_m");
        if (majorARaw)
            w.value(6370000.0 + static_cast<double>(*majorARaw) / 1000.0);
        else
            w.null();
        break;
    }
    }
    w.endObject();
}

} // namespace gnss::nemerix
