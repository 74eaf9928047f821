// GST: GNSS pseudorange error statistics (NMEA 0183 4.11 §6.3).
//
//   $--GST,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x*hh
//          0 time, 1 RMS of range residuals, 2 error ellipse semi-major (m), 3 semi-minor (m),
//          4 orientation (deg), 5 sd latitude (m), 6 sd longitude (m), 7 sd altitude (m)
#include "nmea_messages.h"

namespace gnss::nmea {

const MessageType Gst::kType{"GST"};

const FieldRow<Gst> Gst::kFields[] = {
        {&Gst::time, "time", "time"},
        {&Gst::rms, "rms", "rms"},
        {&Gst::sdMajor, "semi-major", "sd_major"},
        {&Gst::sdMinor, "semi-minor", "sd_minor"},
        {&Gst::orientation, "orientation", "orientation"},
        {&Gst::sdLat, "sd latitude", "sd_lat"},
        {&Gst::sdLon, "sd longitude", "sd_lon"},
        {&Gst::sdAlt, "sd altitude", "sd_alt"},
};

} // namespace gnss::nmea
