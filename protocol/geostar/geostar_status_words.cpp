// RQUERY words, tables 7-9 of the GeoS-5 NMEA protocol v4.0 (section 3.11).
#include "geostar/geostar_status_words.h"

#include <cstdio>
#include <span>
#include <string>

namespace gnss::geostar {
namespace {

constexpr bool bit(std::uint32_t w, int n) {
    return ((w >> n) & 1u) != 0;
}
constexpr int bits(std::uint32_t w, int hi, int lo) {
    return static_cast<int>((w >> lo) & ((1u << (hi - lo + 1)) - 1u));
}

// One flag of a word: its bit, the field it fills and its JSON key; a flag with words for its two
// states is written as the word ("state": "active"), else as true/false. Tables list a word's
// flags from the highest bit down, the order its JSON keeps.
template <class W> struct Flag {
    int bit;
    bool W::*field;
    std::string_view key;
    std::string_view whenClear = {}, whenSet = {};
};

template <class W> void readFlags(std::uint32_t w, W &word, std::span<const Flag<W>> flags) {
    for (const Flag<W> &f : flags) word.*f.field = bit(w, f.bit);
}

// The flags of bits hi down to lo.
template <class W>
void writeFlags(JsonWriter &w, const W &word, std::span<const Flag<W>> flags, int hi, int lo) {
    for (const Flag<W> &f : flags) {
        if (f.bit > hi || f.bit < lo) continue;
        const bool on = word.*f.field;
        if (f.whenSet.empty())
            w.field(f.key, on);
        else
            w.field(f.key, on ? f.whenSet : f.whenClear);
    }
}

// Sets the bits of one word as decode reads them; the first field that does not fit is refused.
class WordBuilder {
public:
    WordBuilder &bit(int n, bool on) {
        if (on) w_ |= 1u << n;
        return *this;
    }
    template <class W> WordBuilder &flags(const W &word, std::span<const Flag<W>> flags) {
        for (const Flag<W> &f : flags) bit(f.bit, word.*f.field);
        return *this;
    }
    WordBuilder &bits(int hi, int lo, int v, const char *name) {
        const int max = (1 << (hi - lo + 1)) - 1;
        if (v >= 0 && v <= max)
            w_ |= static_cast<std::uint32_t>(v) << lo;
        else if (why_.empty())
            why_ = refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                           {name, std::to_string(v), "0.." + std::to_string(max)});
        return *this;
    }
    EncodedWord done(std::uint32_t raw, std::uint32_t reservedMask) const {
        EncodedWord e;
        if (!why_.empty())
            e.refusal = why_;
        else
            e.word = w_ | (raw & reservedMask);
        return e;
    }

private:
    std::uint32_t w_ = 0;
    Refusal why_;
};

void writeHex(JsonWriter &w, std::string_view key, std::uint32_t v) {
    char buf[12];
    std::snprintf(buf, sizeof buf, "%08X", static_cast<unsigned>(v));
    w.field(key, std::string_view(buf));
}

} // namespace

std::string_view toString(AntennaState a) {
    switch (a) {
    case AntennaState::NotMeasured: return "not_measured";
    case AntennaState::Overloaded: return "overloaded";
    case AntennaState::Disconnected: return "disconnected";
    case AntennaState::Ok: return "ok";
    }
    return "not_measured";
}

int rateCodeToHz(int code) {
    switch (code) {
    case 0: return 10;
    case 1: return 5;
    case 2: return 2;
    case 3: return 1;
    default: return 0;
    }
}

int rateHzToCode(int hz) {
    for (int code = 0; code <= 3; ++code)
        if (rateCodeToHz(code) == hz) return code;
    return -1;
}

// ---- Table 7 ----------------------------------------------------------------------------------

using SW = StatusWord;
constexpr Flag<SW> kStatusFlags[] = {
        {31, &SW::jammingDetected, "jamming_detected"},
        {30, &SW::flashWriteInProgress, "flash_write_in_progress"},
        {28, &SW::geoPathActive, "geopath_active"},
        {27, &SW::referenceWithinThreshold, "reference_within_threshold"},
        {26, &SW::averagingInProgress, "averaging_in_progress"},
        {25, &SW::rtcmCorrectionsUsed, "rtcm_corrections_used"},
        {24, &SW::sbasCorrectionsUsed, "sbas_corrections_used"},
        {23, &SW::active, "state", "sleep", "active"},
        {22, &SW::differential, "solution_type", "autonomous", "differential"},
        {21, &SW::extrapolated, "extrapolated"},
        {20, &SW::stationary, "stationary"},
        {19, &SW::solutionAvailable, "solution_available"},
        {18, &SW::validSinceStart, "valid_since_start"},
        {16, &SW::solution2D, "solution_dim", "3D", "2D"},
        {15, &SW::clockRestoredHotStart, "clock_restored_hot_start"},
        {14, &SW::gpsIonoUtcAvailable, "gps_iono_utc_available"},
        {13, &SW::dateFromNavMessage, "date_from_nav_message"},
        {12, &SW::timeFromNavMessage, "time_from_nav_message"},
        {11, &SW::qzssAlmanac, "almanac_qzss"},
        {10, &SW::galileoAlmanac, "almanac_galileo"},
        {9, &SW::glonassAlmanac, "almanac_glonass"},
        {8, &SW::gpsAlmanac, "almanac_gps"},
        // 7:6 antenna
        {5, &SW::glonassAgcOk, "agc_glonass_ok"},
        {4, &SW::gpsAgcOk, "agc_gps_ok"},
        {3, &SW::settingsLoadedFromFlash, "settings_loaded_from_flash"},
        {2, &SW::pllOk, "pll_ok"},
        {1, &SW::rtcOk, "rtc_ok"},
        {0, &SW::backupRamOk, "backup_ram_ok"},
};

StatusWord StatusWord::decode(std::uint32_t w) {
    StatusWord s;
    s.raw = w;
    readFlags<SW>(w, s, kStatusFlags);
    s.antenna = static_cast<AntennaState>(bits(w, 7, 6));
    return s;
}

EncodedWord StatusWord::encode() const {
    WordBuilder b;
    b.flags<SW>(*this, kStatusFlags)
            .bits(7, 6, static_cast<int>(antenna), "status word bits 7:6 (antenna)");
    return b.done(raw, kReservedMask);
}

void StatusWord::writeJson(JsonWriter &w) const {
    w.beginObject();
    writeHex(w, "raw", raw);
    writeFlags<SW>(w, *this, kStatusFlags, 31, 8);
    w.field("antenna", toString(antenna));
    writeFlags<SW>(w, *this, kStatusFlags, 5, 0);
    writeHex(w, "reserved_bits", raw & kReservedMask);
    w.endObject();
}

// ---- Table 8 ----------------------------------------------------------------------------------

using CR1 = ConfigRegister1;
constexpr Flag<CR1> kConfig1Flags[] = {
        {30, &CR1::antennaPower, "antenna_power"},
        {28, &CR1::fixedCoordinatesMode, "operating_mode", "autonomous_or_differential",
         "fixed_coordinates"},
        {27, &CR1::raim, "raim"},
        {26, &CR1::smoothedPseudoranges, "smoothed_pseudoranges"},
        {25, &CR1::fixByRequest, "power_saving_type", "RELAXED FIX", "FIX-BY-REQUEST"},
        {24, &CR1::powerSavingEnabled, "power_saving_enabled"},
        // 23:21 dynamics, 19:18 rate
        {15, &CR1::kalmanFilter, "kalman_filter"},
        {14, &CR1::firstFix2DAllowed, "first_fix_2d_allowed"},
        {13, &CR1::mode2DAllowed, "mode_2d_allowed"},
        {12, &CR1::geoPath, "geopath"},
        // 11:9 1PPS time scale
        {8, &CR1::ppsNegative, "pps_polarity", "positive", "negative"},
        {7, &CR1::ppsEnabled, "pps_enabled"},
        {6, &CR1::searchUnusedSystems, "search_unused_systems"},
        {4, &CR1::sbas, "sbas"},
        {3, &CR1::qzss, "qzss"},
        {2, &CR1::galileo, "galileo"},
        {1, &CR1::gps, "gps"},
        {0, &CR1::glonass, "glonass"},
};

ConfigRegister1 ConfigRegister1::decode(std::uint32_t w) {
    ConfigRegister1 c;
    c.raw = w;
    readFlags<CR1>(w, c, kConfig1Flags);
    c.dynamicsCode = bits(w, 23, 21);
    c.rateCode = bits(w, 19, 18);
    c.rateHz = rateCodeToHz(c.rateCode);
    c.ppsTimeScaleCode = bits(w, 11, 9);
    return c;
}

EncodedWord ConfigRegister1::encode() const {
    WordBuilder b;
    b.flags<CR1>(*this, kConfig1Flags)
            .bits(23, 21, dynamicsCode, "configuration register 1 bits 23:21 (dynamics)")
            .bits(19, 18, rateCode, "configuration register 1 bits 19:18 (rate code)")
            .bits(11, 9, ppsTimeScaleCode, "configuration register 1 bits 11:9 (1PPS time scale)");
    return b.done(raw, kReservedMask);
}

std::string_view ConfigRegister1::dynamicsName() const {
    switch (dynamicsCode) {
    case 0: return "auto";
    case 1: return "pedestrian_car";
    case 2: return "marine";
    case 3: return "airborne";
    case 4: return "high_dynamics";
    default: return "undefined";
    }
}

std::string_view ConfigRegister1::ppsTimeScaleName() const {
    switch (ppsTimeScaleCode) {
    case 0: return "GPS";
    case 1: return "UTC";
    case 2: return "GLONASS";
    case 3: return "UTC(SU)";
    default: return "reserved";
    }
}

void ConfigRegister1::writeJson(JsonWriter &w) const {
    w.beginObject();
    writeHex(w, "raw", raw);
    writeFlags<CR1>(w, *this, kConfig1Flags, 30, 24);
    w.field("dynamics_code", dynamicsCode)
            .field("dynamics", dynamicsName())
            .field("rate_code", rateCode)
            .field("rate_hz", rateHz);
    writeFlags<CR1>(w, *this, kConfig1Flags, 15, 12);
    w.field("pps_time_scale_code", ppsTimeScaleCode).field("pps_time_scale", ppsTimeScaleName());
    writeFlags<CR1>(w, *this, kConfig1Flags, 8, 0);
    writeHex(w, "reserved_bits", raw & kReservedMask);
    w.endObject();
}

// ---- Table 9 ----------------------------------------------------------------------------------

using CR2 = ConfigRegister2;
constexpr Flag<CR2> kConfig2Flags[] = {
        // 31:16 receiver type, 15:14 datum
        {8, &CR2::differentialAllowed, "differential_allowed"},
        {4, &CR2::sbasTestModeAllowed, "sbas_test_mode_allowed"},
        {3, &CR2::useAllSatellites, "use_all_satellites"},
        {2, &CR2::sbasPrnAuto, "sbas_prn", "user", "auto"},
};

ConfigRegister2 ConfigRegister2::decode(std::uint32_t w) {
    ConfigRegister2 c;
    c.raw = w;
    c.receiverTypeCode = static_cast<std::uint16_t>(w >> 16);
    c.datumCode = bits(w, 15, 14);
    readFlags<CR2>(w, c, kConfig2Flags);
    return c;
}

EncodedWord ConfigRegister2::encode() const {
    WordBuilder b;
    b.bits(31, 16, receiverTypeCode, "configuration register 2 bits 31:16 (receiver type)")
            .bits(15, 14, datumCode, "configuration register 2 bits 15:14 (datum)")
            .flags<CR2>(*this, kConfig2Flags);
    return b.done(raw, kReservedMask);
}

std::string_view ConfigRegister2::receiverType() const {
    switch (receiverTypeCode) {
    case 0xF7FF: return "GeoS-5M";
    case 0xF7FE: return "GeoS-5MR";
    case 0xF7FD: return "GeoS-5MH";
    case 0xD7FE: return "GeoS-5MP";
    default: return {};
    }
}

std::string_view ConfigRegister2::datumName() const {
    switch (datumCode) {
    case 0: return "WGS-84";
    case 1: return "PZ-90.11";
    case 2: return "user";
    default: return "undefined";
    }
}

void ConfigRegister2::writeJson(JsonWriter &w) const {
    w.beginObject();
    writeHex(w, "raw", raw);
    char code[8];
    std::snprintf(code, sizeof code, "%04X", static_cast<unsigned>(receiverTypeCode));
    w.field("receiver_type_code", std::string_view(code));
    if (receiverType().empty())
        w.key("receiver_type").null();
    else
        w.field("receiver_type", receiverType());
    w.field("datum_code", datumCode).field("datum", datumName());
    writeFlags<CR2>(w, *this, kConfig2Flags, 8, 0);
    writeHex(w, "reserved_bits", raw & kReservedMask);
    w.endObject();
}

} // namespace gnss::geostar
