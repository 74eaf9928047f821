// RQUERY words, tables 7-9 of the GeoS-5 NMEA protocol v4.0 (section 3.11).
#include "geostar_status_words.h"

#include <cstdio>
#include <string>

namespace gnss::geostar {
namespace {

constexpr bool bit(std::uint32_t w, int n) {
    return ((w >> n) & 1u) != 0;
}
constexpr int bits(std::uint32_t w, int hi, int lo) {
    return static_cast<int>((w >> lo) & ((1u << (hi - lo + 1)) - 1u));
}

// Sets the bits of one word as decode reads them; the first field that does not fit is refused.
class WordBuilder {
public:
    WordBuilder &bit(int n, bool on) {
        if (on) w_ |= 1u << n;
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

StatusWord StatusWord::decode(std::uint32_t w) {
    StatusWord s;
    s.raw = w;
    s.jammingDetected = bit(w, 31);
    s.flashWriteInProgress = bit(w, 30);
    s.geoPathActive = bit(w, 28);
    s.referenceWithinThreshold = bit(w, 27);
    s.averagingInProgress = bit(w, 26);
    s.rtcmCorrectionsUsed = bit(w, 25);
    s.sbasCorrectionsUsed = bit(w, 24);
    s.active = bit(w, 23);
    s.differential = bit(w, 22);
    s.extrapolated = bit(w, 21);
    s.stationary = bit(w, 20);
    s.solutionAvailable = bit(w, 19);
    s.validSinceStart = bit(w, 18);
    s.solution2D = bit(w, 16);
    s.clockRestoredHotStart = bit(w, 15);
    s.gpsIonoUtcAvailable = bit(w, 14);
    s.dateFromNavMessage = bit(w, 13);
    s.timeFromNavMessage = bit(w, 12);
    s.qzssAlmanac = bit(w, 11);
    s.galileoAlmanac = bit(w, 10);
    s.glonassAlmanac = bit(w, 9);
    s.gpsAlmanac = bit(w, 8);
    s.antenna = static_cast<AntennaState>(bits(w, 7, 6));
    s.glonassAgcOk = bit(w, 5);
    s.gpsAgcOk = bit(w, 4);
    s.settingsLoadedFromFlash = bit(w, 3);
    s.pllOk = bit(w, 2);
    s.rtcOk = bit(w, 1);
    s.backupRamOk = bit(w, 0);
    return s;
}

EncodedWord StatusWord::encode() const {
    WordBuilder b;
    b.bit(31, jammingDetected)
            .bit(30, flashWriteInProgress)
            .bit(28, geoPathActive)
            .bit(27, referenceWithinThreshold)
            .bit(26, averagingInProgress)
            .bit(25, rtcmCorrectionsUsed)
            .bit(24, sbasCorrectionsUsed)
            .bit(23, active)
            .bit(22, differential)
            .bit(21, extrapolated)
            .bit(20, stationary)
            .bit(19, solutionAvailable)
            .bit(18, validSinceStart)
            .bit(16, solution2D)
            .bit(15, clockRestoredHotStart)
            .bit(14, gpsIonoUtcAvailable)
            .bit(13, dateFromNavMessage)
            .bit(12, timeFromNavMessage)
            .bit(11, qzssAlmanac)
            .bit(10, galileoAlmanac)
            .bit(9, glonassAlmanac)
            .bit(8, gpsAlmanac)
            .bits(7, 6, static_cast<int>(antenna), "status word bits 7:6 (antenna)")
            .bit(5, glonassAgcOk)
            .bit(4, gpsAgcOk)
            .bit(3, settingsLoadedFromFlash)
            .bit(2, pllOk)
            .bit(1, rtcOk)
            .bit(0, backupRamOk);
    return b.done(raw, kReservedMask);
}

void StatusWord::writeJson(JsonWriter &w) const {
    w.beginObject();
    writeHex(w, "raw", raw);
    w.field("jamming_detected", jammingDetected)
            .field("flash_write_in_progress", flashWriteInProgress)
            .field("geopath_active", geoPathActive)
            .field("reference_within_threshold", referenceWithinThreshold)
            .field("averaging_in_progress", averagingInProgress)
            .field("rtcm_corrections_used", rtcmCorrectionsUsed)
            .field("sbas_corrections_used", sbasCorrectionsUsed)
            .field("state", std::string_view(active ? "active" : "sleep"))
            .field("solution_type", std::string_view(differential ? "differential" : "autonomous"))
            .field("extrapolated", extrapolated)
            .field("stationary", stationary)
            .field("solution_available", solutionAvailable)
            .field("valid_since_start", validSinceStart)
            .field("solution_dim", std::string_view(solution2D ? "2D" : "3D"))
            .field("clock_restored_hot_start", clockRestoredHotStart)
            .field("gps_iono_utc_available", gpsIonoUtcAvailable)
            .field("date_from_nav_message", dateFromNavMessage)
            .field("time_from_nav_message", timeFromNavMessage)
            .field("almanac_qzss", qzssAlmanac)
            .field("almanac_galileo", galileoAlmanac)
            .field("almanac_glonass", glonassAlmanac)
            .field("almanac_gps", gpsAlmanac)
            .field("antenna", toString(antenna))
            .field("agc_glonass_ok", glonassAgcOk)
            .field("agc_gps_ok", gpsAgcOk)
            .field("settings_loaded_from_flash", settingsLoadedFromFlash)
            .field("pll_ok", pllOk)
            .field("rtc_ok", rtcOk)
            .field("backup_ram_ok", backupRamOk);
    writeHex(w, "reserved_bits", raw & kReservedMask);
    w.endObject();
}

// ---- Table 8 ----------------------------------------------------------------------------------

ConfigRegister1 ConfigRegister1::decode(std::uint32_t w) {
    ConfigRegister1 c;
    c.raw = w;
    c.antennaPower = bit(w, 30);
    c.fixedCoordinatesMode = bit(w, 28);
    c.raim = bit(w, 27);
    c.smoothedPseudoranges = bit(w, 26);
    c.fixByRequest = bit(w, 25);
    c.powerSavingEnabled = bit(w, 24);
    c.dynamicsCode = bits(w, 23, 21);
    c.rateCode = bits(w, 19, 18);
    c.rateHz = rateCodeToHz(c.rateCode);
    c.kalmanFilter = bit(w, 15);
    c.firstFix2DAllowed = bit(w, 14);
    c.mode2DAllowed = bit(w, 13);
    c.geoPath = bit(w, 12);
    c.ppsTimeScaleCode = bits(w, 11, 9);
    c.ppsNegative = bit(w, 8);
    c.ppsEnabled = bit(w, 7);
    c.searchUnusedSystems = bit(w, 6);
    c.sbas = bit(w, 4);
    c.qzss = bit(w, 3);
    c.galileo = bit(w, 2);
    c.gps = bit(w, 1);
    c.glonass = bit(w, 0);
    return c;
}

EncodedWord ConfigRegister1::encode() const {
    WordBuilder b;
    b.bit(30, antennaPower)
            .bit(28, fixedCoordinatesMode)
            .bit(27, raim)
            .bit(26, smoothedPseudoranges)
            .bit(25, fixByRequest)
            .bit(24, powerSavingEnabled)
            .bits(23, 21, dynamicsCode, "configuration register 1 bits 23:21 (dynamics)")
            .bits(19, 18, rateCode, "configuration register 1 bits 19:18 (rate code)")
            .bit(15, kalmanFilter)
            .bit(14, firstFix2DAllowed)
            .bit(13, mode2DAllowed)
            .bit(12, geoPath)
            .bits(11, 9, ppsTimeScaleCode, "configuration register 1 bits 11:9 (1PPS time scale)")
            .bit(8, ppsNegative)
            .bit(7, ppsEnabled)
            .bit(6, searchUnusedSystems)
            .bit(4, sbas)
            .bit(3, qzss)
            .bit(2, galileo)
            .bit(1, gps)
            .bit(0, glonass);
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
    w.field("antenna_power", antennaPower)
            .field("operating_mode",
                   std::string_view(fixedCoordinatesMode ? "fixed_coordinates"
                                                         : "autonomous_or_differential"))
            .field("raim", raim)
            .field("smoothed_pseudoranges", smoothedPseudoranges)
            .field("power_saving_type",
                   std::string_view(fixByRequest ? "FIX-BY-REQUEST" : "RELAXED FIX"))
            .field("power_saving_enabled", powerSavingEnabled)
            .field("dynamics_code", dynamicsCode)
            .field("dynamics", dynamicsName())
            .field("rate_code", rateCode)
            .field("rate_hz", rateHz)
            .field("kalman_filter", kalmanFilter)
            .field("first_fix_2d_allowed", firstFix2DAllowed)
            .field("mode_2d_allowed", mode2DAllowed)
            .field("geopath", geoPath)
            .field("pps_time_scale_code", ppsTimeScaleCode)
            .field("pps_time_scale", ppsTimeScaleName())
            .field("pps_polarity", std::string_view(ppsNegative ? "negative" : "positive"))
            .field("pps_enabled", ppsEnabled)
            .field("search_unused_systems", searchUnusedSystems)
            .field("sbas", sbas)
            .field("qzss", qzss)
            .field("galileo", galileo)
            .field("gps", gps)
            .field("glonass", glonass);
    writeHex(w, "reserved_bits", raw & kReservedMask);
    w.endObject();
}

// ---- Table 9 ----------------------------------------------------------------------------------

ConfigRegister2 ConfigRegister2::decode(std::uint32_t w) {
    ConfigRegister2 c;
    c.raw = w;
    c.receiverTypeCode = static_cast<std::uint16_t>(w >> 16);
    c.datumCode = bits(w, 15, 14);
    c.differentialAllowed = bit(w, 8);
    c.sbasTestModeAllowed = bit(w, 4);
    c.useAllSatellites = bit(w, 3);
    c.sbasPrnAuto = bit(w, 2);
    return c;
}

EncodedWord ConfigRegister2::encode() const {
    WordBuilder b;
    b.bits(31, 16, receiverTypeCode, "configuration register 2 bits 31:16 (receiver type)")
            .bits(15, 14, datumCode, "configuration register 2 bits 15:14 (datum)")
            .bit(8, differentialAllowed)
            .bit(4, sbasTestModeAllowed)
            .bit(3, useAllSatellites)
            .bit(2, sbasPrnAuto);
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
    w.field("datum_code", datumCode)
            .field("datum", datumName())
            .field("differential_allowed", differentialAllowed)
            .field("sbas_test_mode_allowed", sbasTestModeAllowed)
            .field("use_all_satellites", useAllSatellites)
            .field("sbas_prn", std::string_view(sbasPrnAuto ? "auto" : "user"));
    writeHex(w, "reserved_bits", raw & kReservedMask);
    w.endObject();
}

} // namespace gnss::geostar
