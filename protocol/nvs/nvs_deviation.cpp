// 4.19 PNVGSDP, 4.20 PNVGSDV, 4.21 PNVGSDH: standard deviation (rms) of position, velocity and
// heading, with the mode indicator (A D F R E N).
//
//   $PNVGSDP,hhmmss.ss,x.x,x.x,x.x,a*hh   0 time, 1 latitude, 2 longitude, 3 height (m), 4 mode
//   $PNVGSDV,hhmmss.ss,x.x,x.x,x.x,a*hh   0 time, 1 north, 2 east, 3 vertical (m/s), 4 mode
//   $PNVGSDH,hhmmss.ss,x.x,a*hh           0 time, 1 heading (deg), 2 mode
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Sdp::kType{"PNVGSDP"};
const MessageType Sdv::kType{"PNVGSDV"};
const MessageType Sdh::kType{"PNVGSDH"};

// Deviations in millimetres, mm/s and thousandths of a degree.
const FieldRow<Sdp> Sdp::kFields[] = {
        {&Sdp::time, "time", "time"},
        {&Sdp::sdLat, "latitude deviation", "sd_lat", {3, 0, kMaxMetres}},
        {&Sdp::sdLon, "longitude deviation", "sd_lon", {3, 0, kMaxMetres}},
        {&Sdp::sdHeight, "height deviation", "sd_height", {3, 0, kMaxMetres}},
        {&Sdp::mode, "mode", "mode"},
};
const FieldRow<Sdv> Sdv::kFields[] = {
        {&Sdv::time, "time", "time"},
        {&Sdv::sdVelNorth, "north velocity deviation", "sd_vel_north", {3, 0, kMaxSpeed}},
        {&Sdv::sdVelEast, "east velocity deviation", "sd_vel_east", {3, 0, kMaxSpeed}},
        {&Sdv::sdVelUp, "vertical velocity deviation", "sd_vel_up", {3, 0, kMaxSpeed}},
        {&Sdv::mode, "mode", "mode"},
};
const FieldRow<Sdh> Sdh::kFields[] = {
        {&Sdh::time, "time", "time"},
        {&Sdh::sdHeading, "heading deviation", "sd_heading", {3, 0, 360}},
        {&Sdh::mode, "mode", "mode"},
};

EncodeResult encodeSdp(const Sdp &m) {
    return encodeRows(m, Sdp::kFields);
}

EncodeResult encodeSdv(const Sdv &m) {
    return encodeRows(m, Sdv::kFields);
}

EncodeResult encodeSdh(const Sdh &m) {
    return encodeRows(m, Sdh::kFields);
}

} // namespace gnss::nvs
