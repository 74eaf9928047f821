#pragma once
// Encoders for the GeoS-5's own output: every proprietary sentence a GeoS-5 sends, built from the
// struct its decoder fills (geostar_messages.h), so that encode(decode(line)) == line for a line
// in the receiver's formatting (tested on the spec's examples). A receiver that answers (the
// simulator) builds its replies here; the input commands' encoders are in geostar_commands.h.
//
// Each returns one complete sentence "$...*hh" (no CR LF), or refuses a value the sentence cannot
// carry (EncodeResult::error names the field and what it accepts) and builds nothing.
#include "geostar/geostar_commands.h"
#include "geostar/geostar_messages.h"
#include "nmea/nmea_messages.h"

#include <string_view>

namespace gnss::geostar {

// 3.11 $GPSGG,RQUERY,name,firmware,ddmmyy,status,config1,config2: the receiver name and the
// firmware as printed (`firmware`; firmwareVersion is the decoder's reading of it), the words as
// eight upper-case hex digits (StatusWord/ConfigRegister1/ConfigRegister2::encode, reserved bits
// from their `raw`). An absent date is an empty field.
EncodeResult encodeRquery(const Rquery &m);

// 3.12 $GPSGG,NQUERY,port,rate code,version,codes...: port 0/1, rate code 0-3, version 2/4 (an
// absent one is an empty field), then `codeCount` per-message codes 0/1/2/3/R ('\0': empty).
EncodeResult encodeNquery(const Nquery &m);

// 3.13 $GPSGG,JAMDET, (with its trailing comma).
EncodeResult encodeJamdet(const Jamdet &m = {});

// 3.10 $GPRLM,beacon,hhmmss.ss,code,parameters: beacon 15 hex digits and parameters 4 or 24, as
// given; the code as one upper-case hex digit.
EncodeResult encodeRlm(const Rlm &m);

// 3.3 A subsidiary GNS sentence of a mixed-constellation fix, one per system (talker GP, GL, GA
// or GQ): time and the system's satellites used in the mode position; when the system has a DGPS
// age or station (or a navigational status), those follow:
//   $GPGNS,080520.00,,,,,11,,,,,*40                (no corrections: 11 fields)
//   $GPGNS,080606.00,,,,,11,,,,,001.0,0000,*68     (age 000.0-999.9 s, station 0000-4095)
// Position, mode, HDOP, altitude and geoid fields belong to the main sentence: not printed.
EncodeResult encodeSubsidiaryGns(std::string_view talker, const nmea::Gns &m);

} // namespace gnss::geostar
