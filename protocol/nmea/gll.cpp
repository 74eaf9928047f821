// GLL: geographic position, latitude/longitude (NMEA 0183 4.11 §6.3).
//
//   $--GLL,llll.ll,a,yyyyy.yy,a,hhmmss.ss,A,a*hh
//          0 lat  1  2 lon   3  4 time   5 status 6 mode (2.3+)
#include "nmea/nmea_messages.h"

namespace gnss::nmea {

const MessageType Gll::kType{"GLL"};

const FieldRow<Gll> Gll::kFields[] = {
        {&Gll::lat, "latitude", "lat", {}, FieldForm::Latitude},
        {&Gll::lon, "longitude", "lon", {}, FieldForm::Longitude},
        {&Gll::time, "time", "time"},
        {&Gll::status, "status", "status"},
        {&Gll::mode, "mode", "mode"},
};

} // namespace gnss::nmea
