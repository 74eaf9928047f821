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
#include "nemerix_commands.h"

namespace gnss::nemerix {

const MessageType SettingsReport::kType{"PNMRX603"};
const MessageType PlainCommand::kSettingsQueryType{"PNMRX603 request"};

namespace {
const HexFieldDef kWord{"word", 32, false, 0, ""};
} // namespace

bool decodeSettingsReport(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    bool any = false;
    for (std::size_t i = 0; i < r.count(); ++i)
        if (!r.empty(i)) any = true;
    if (!any) {
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

void SettingsReport::writeJson(JsonWriter &w) const {
    w.beginObject().field("message", number);
    switch (number) {
    case 0: {
        static const char *names[] = {"GGA", "GLL", "GSA", "GSV", "RMC", "VTG", "ZDA"};
        w.key("sequence").beginArray();
        for (const auto &v : sequence) w.value(v);
        w.endArray().key("delay_s").beginObject();
        for (std::size_t i = 0; i < 7; ++i) w.field(names[i], delay[i]);
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
