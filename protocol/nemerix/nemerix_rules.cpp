// The Nemerix sentence table: one row per PNMRX address (outputs and commands alike). The
// standard sentences (GGA, GSA, GSV, RMC, VTG, GLL, ZDA: NMEA 3.0, GPS only) come from the
// standard table. A renamed prefix is mapped back to PNMRX by DecoderOptions::addressAliases.
#include "nemerix/nemerix_dialect_parts.h"
#include "nemerix/nemerix_messages.h"

namespace gnss::nemerix {

namespace {
constexpr SentenceRule kRules[] = {
        {"PNMRX100", AddressMatch::Whole, decodeSerialPort, "Set serial port parameters"},
        {"PNMRX101", AddressMatch::Whole, decodeNavInit, "Navigation initialisation (ECEF)"},
        {"PNMRX103", AddressMatch::Whole, decodeNmeaRates, "NMEA message rate control"},
        {"PNMRX104", AddressMatch::Whole, decodeLlaInit, "LLA navigation initialisation"},
        {"PNMRX106", AddressMatch::Whole, decodeDatum, "Set datum"},
        {"PNMRX107", AddressMatch::Whole, decodeNemerixRates, "Nemerix messages rate control"},
        {"PNMRX108", AddressMatch::Whole, decodeNmeaSequence, "NMEA message sequence control"},
        {"PNMRX110", AddressMatch::Whole, decodeFixSettings, "Fix settings"},
        {"PNMRX111", AddressMatch::Whole, decodeSoftwareReset, "Software reset"},
        {"PNMRX112", AddressMatch::Whole, decodePowerMode, "Operating (power) mode control"},
        {"PNMRX113", AddressMatch::Whole, decodeStopCore, "Stop GPS core activities"},
        {"PNMRX300", AddressMatch::Whole, decodeAlmanac, "Almanac data (one satellite)"},
        {"PNMRX301", AddressMatch::Whole, decodeEphemeris, "Ephemeris data (one subframe)"},
        {"PNMRX302", AddressMatch::Whole, decodeIonosphere, "Ionospheric correction"},
        {"PNMRX303", AddressMatch::Whole, decodeUtc, "GPS-UTC parameters"},
        {"PNMRX304", AddressMatch::Whole, decodeHealth, "GPS constellation health"},
        {"PNMRX600", AddressMatch::Whole, decodeSoftwareVersion,
         "Software version (request/report)"},
        {"PNMRX601", AddressMatch::Whole, decodeIsp, "Enter ISP mode"},
        {"PNMRX602", AddressMatch::Whole, decodeFlashVersion, "Flash content version report"},
        {"PNMRX603", AddressMatch::Whole, decodeSettingsReport, "Settings report (request/report)"},
};
} // namespace

std::span<const SentenceRule> sentenceRules() {
    return kRules;
}

} // namespace gnss::nemerix
