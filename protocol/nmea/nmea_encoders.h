#pragma once
// Encoders for the standard NMEA-0183 sentences, the mirror of the decoders in this folder: each
// takes the same struct its decoder fills, so `decode(encode(m)) == m` holds field by field (the
// round trip is tested). Used by the receiver simulator; any tool that needs to write standard
// sentences (log generators, a base-station NMEA output) can use them too.
//
// Every function returns one complete sentence "$ttXXX,...*HH" (no CR LF). Empty optionals are
// written as empty fields. The talker ("GP", "GN", "GL", ...) is chosen by the caller.
#include "nmea/nmea_messages.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::nmea {

// How many decimals the receiver prints (NVS sets these with PNVGNME).
struct EncodeFormat {
    int timeDecimals = 2;     // hhmmss.ss
    int positionDecimals = 4; // decimals of the minutes: ddmm.mmmm
};

// Field helpers (also used by proprietary encoders that carry time or position fields).
std::string formatTime(const TimeOfDay &t, int decimals);                   // "hhmmss.ss"
std::string formatLatitude(std::optional<double> lat, int minuteDecimals);  // "ddmm.mmmm,N" / ","
std::string formatLongitude(std::optional<double> lon, int minuteDecimals); // "dddmm.mmmm,E" / ","
std::string formatDate(const Date &d);                                      // "ddmmyy"
// TimeOfDay from seconds since midnight (rounded to the printed decimals by the formatter).
TimeOfDay timeOfDay(double secondsOfDay, int decimals);

std::string encodeGga(std::string_view talker, const Gga &m, const EncodeFormat &f = {});
std::string encodeGll(std::string_view talker, const Gll &m, const EncodeFormat &f = {});
std::string encodeGns(std::string_view talker, const Gns &m, const EncodeFormat &f = {});
// GSA: prints 12 id fields (padded with empty ones; more than 12 ids are printed as given), then
// PDOP, HDOP, VDOP and the system id when set.
std::string encodeGsa(std::string_view talker, const Gsa &m);
// One GSV sentence (up to four satellites of m.satellites).
std::string encodeGsv(std::string_view talker, const Gsv &m);
// The whole GSV group for a list of satellites: ceil(n/4) sentences (one with no satellites when
// the list is empty), numbered 1..n, each carrying the total in view and the signal id when set.
std::vector<std::string> encodeGsvGroup(std::string_view talker,
                                        std::span<const GsvSatellite> satellites,
                                        std::optional<int> signalId = std::nullopt);
std::string encodeRmc(std::string_view talker, const Rmc &m, const EncodeFormat &f = {});
std::string encodeVtg(std::string_view talker, const Vtg &m);
std::string encodeZda(std::string_view talker, const Zda &m, const EncodeFormat &f = {});
std::string encodeHdt(std::string_view talker, const Hdt &m);
std::string encodeGst(std::string_view talker, const Gst &m, const EncodeFormat &f = {});
std::string encodeTxt(std::string_view talker, const Txt &m);

} // namespace gnss::nmea
