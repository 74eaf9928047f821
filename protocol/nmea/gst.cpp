// GST: GNSS pseudorange error statistics (NMEA 0183 4.11 §6.3).
//
//   $--GST,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x*hh
//          0 time, 1 RMS of range residuals, 2 error ellipse semi-major (m), 3 semi-minor (m),
//          4 orientation (deg), 5 sd latitude (m), 6 sd longitude (m), 7 sd altitude (m)
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Gst::kType{"GST"};

// Metres with 3 decimals, the orientation (degrees) with 1, as the encoder prints them.
const FieldRow<Gst> Gst::kFields[] = {
        {&Gst::time, "time", "time"},
        {&Gst::rms, "rms", "rms", {3}},
        {&Gst::sdMajor, "semi-major", "sd_major", {3}},
        {&Gst::sdMinor, "semi-minor", "sd_minor", {3}},
        {&Gst::orientation, "orientation", "orientation", {1}},
        {&Gst::sdLat, "sd latitude", "sd_lat", {3}},
        {&Gst::sdLon, "sd longitude", "sd_lon", {3}},
        {&Gst::sdAlt, "sd altitude", "sd_alt", {3}},
};

} // namespace gnss::nmea
