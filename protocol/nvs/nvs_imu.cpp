// 4.10 PNVGIMU: attitude and NED acceleration from the IMU (MEMS).
//
//   rev 1.5+  $PNVGIMU,hhmmss.ss,x,x,x,x,x,x*hh
//             0 time, 1 roll, 2 pitch, 3 yaw (deg), 4 an, 5 ae, 6 ad (m/s^2, north/east/down)
//   pre-1.5   $PNVGIMU,x,x,x,x,x,x*hh   (no time tag: the same fields shifted by one)
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

#include <span>

namespace gnss::nvs {

const MessageType Imu::kType{"PNVGIMU"};

// Angles in hundredths of a degree, accelerations in mm/s^2.
const FieldRow<Imu> Imu::kFields[] = {
        {&Imu::time, "time", "time"},
        {&Imu::roll, "roll", "roll", {2, -360, 360}},
        {&Imu::pitch, "pitch", "pitch", {2, -90, 90}},
        {&Imu::yaw, "yaw", "yaw", {2, -360, 360}},
        {&Imu::accNorth,
         "north acceleration",
         "acc_north",
         {3, -kMaxAcceleration, kMaxAcceleration}},
        {&Imu::accEast, "east acceleration", "acc_east", {3, -kMaxAcceleration, kMaxAcceleration}},
        {&Imu::accDown, "down acceleration", "acc_down", {3, -kMaxAcceleration, kMaxAcceleration}},
};

namespace {

// Every row, or (firmware before 1.5, no time tag) the rows after the time.
std::span<const FieldRow<Imu>> imuFields(bool timed) {
    return std::span(Imu::kFields).subspan(timed ? 0 : 1);
}

} // namespace

bool decodeImu(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Imu>(s, ctx, 6, [&](FieldReader &r, Imu &m) {
        readFields(r, m, imuFields(s.fieldCount() >= 7));
    });
}

// Without a time, the form of firmware before 1.5 (no time field).
EncodeResult encodeImu(const Imu &m) {
    return encodeRows(m, imuFields(m.time.has_value()));
}

} // namespace gnss::nvs
