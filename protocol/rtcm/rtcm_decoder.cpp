// decodeMessage: reads DF002 and hands the payload to the family's decoder.
#include "rtcm/message_decoders.h"

namespace gnss::rtcm {
namespace {

// Messages this library does not decode but whose DF003 reference station id follows DF002
// directly: system parameters (1013), Unicode text (1029).
bool stationFollowsNumber(unsigned n) {
    return n == 1013 || n == 1029;
}

} // namespace

std::string_view systemName(System s) {
    switch (s) {
    case System::Gps: return "GPS";
    case System::Glonass: return "GLONASS";
    case System::Galileo: return "Galileo";
    case System::Sbas: return "SBAS";
    case System::Qzss: return "QZSS";
    case System::BeiDou: return "BeiDou";
    case System::NavIC: return "NavIC";
    }
    return "unknown";
}

RtcmMessage decodeMessage(std::span<const std::uint8_t> payload) {
    RtcmMessage m;
    m.length = payload.size();
    BitReader r(payload);
    if (payload.empty()) {
        m.error = "empty message (keep-alive frame)";
        return m;
    }
    if (!r.has(12)) {
        m.error = "payload shorter than a message number";
        return m;
    }
    m.number = static_cast<unsigned>(r.u(12));
    switch (m.number) {
    case 1005:
    case 1006: decodeStationArp(r, m); break;
    case 1007:
    case 1008:
    case 1033: decodeAntennaInfo(r, m); break;
    case 1019:
    case 1020:
    case 1042:
    case 1044:
    case 1045:
    case 1046: decodeEphemeris(r, m); break;
    case 1230: decodeGlonassBiases(r, m); break;
    default:
        if (isMsm(m.number)) {
            decodeMsm(r, m);
        } else if (isLegacyObservables(m.number)) {
            decodeLegacyObservables(r, m);
        } else if (stationFollowsNumber(m.number)) {
            if (r.has(12))
                m.station = static_cast<unsigned>(r.u(12));
            else
                m.error = "truncated before the station id";
        }
    }
    return m;
}

} // namespace gnss::rtcm
