#pragma once
// The per-family decoders behind decodeMessage() (one file each). Internal to gnss_rtcm: each
// is called with the reader just past DF002 and fills the message's station, body or error.
#include "rtcm/bit_reader.h"
#include "rtcm/rtcm_messages.h"

namespace gnss::rtcm {

void decodeStationArp(BitReader &r, RtcmMessage &m);        // station_messages.cpp
void decodeAntennaInfo(BitReader &r, RtcmMessage &m);       // station_messages.cpp
void decodeMsm(BitReader &r, RtcmMessage &m);               // msm.cpp
void decodeEphemeris(BitReader &r, RtcmMessage &m);         // ephemeris_messages.cpp
void decodeGlonassBiases(BitReader &r, RtcmMessage &m);     // glonass_biases.cpp
void decodeLegacyObservables(BitReader &r, RtcmMessage &m); // legacy_observables.cpp

} // namespace gnss::rtcm
