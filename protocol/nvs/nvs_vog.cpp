// 4.13 PNVGVOG: velocity over ground.
//
//   $PNVGVOG,hhmmss.ss,x.x,x.x,x.x,a*hh
//            0 time, 1 north, 2 east, 3 vertical velocity (m/s), 4 mode (A D F R E N)
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Vog::kType{"PNVGVOG"};

// Velocities in mm/s.
const FieldRow<Vog> Vog::kFields[] = {
        {&Vog::time, "time", "time"},
        {&Vog::velNorth, "north velocity", "vel_north", {3, -kMaxSpeed, kMaxSpeed}},
        {&Vog::velEast, "east velocity", "vel_east", {3, -kMaxSpeed, kMaxSpeed}},
        {&Vog::velUp, "vertical velocity", "vel_up", {3, -kMaxSpeed, kMaxSpeed}},
        {&Vog::mode, "mode", "mode"},
};

EncodeResult encodeVog(const Vog &m) {
    return encodeRows(m, Vog::kFields);
}

} // namespace gnss::nvs
