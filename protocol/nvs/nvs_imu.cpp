// 4.10 PNVGIMU: attitude and NED acceleration from the IMU (MEMS).
//
//   rev 1.5+  $PNVGIMU,hhmmss.ss,x,x,x,x,x,x*hh
//             0 time, 1 roll, 2 pitch, 3 yaw (deg), 4 an, 5 ae, 6 ad (m/s^2, north/east/down)
//   pre-1.5   $PNVGIMU,x,x,x,x,x,x*hh   (no time tag: the same fields shifted by one)
#include "nvs_encoders.h"
#include "nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Imu::kType{"PNVGIMU"};

bool decodeImu(const Sentence &s, DecodeContext &ctx) {
    FieldReader r(s);
    Imu m;
    if (r.require(6)) {
        const std::size_t o = s.fieldCount() >= 7 ? 1 : 0;
        if (o) m.time = r.time(0, "time");
        m.roll = r.real(o + 0, "roll");
        m.pitch = r.real(o + 1, "pitch");
        m.yaw = r.real(o + 2, "yaw");
        m.accNorth = r.real(o + 3, "north acceleration");
        m.accEast = r.real(o + 4, "east acceleration");
        m.accDown = r.real(o + 5, "down acceleration");
    }
    return finishDecode(r, ctx, m);
}

void Imu::writeJson(JsonWriter &w) const {
    w.beginObject()
            .field("time", time)
            .field("roll", roll)
            .field("pitch", pitch)
            .field("yaw", yaw)
            .field("acc_north", accNorth)
            .field("acc_east", accEast)
            .field("acc_down", accDown)
            .endObject();
}

// Angles in hundredths of a degree, accelerations in mm/s^2. Without a time, the form of
// firmware before 1.5 (no time field).
EncodeResult encodeImu(const Imu &m) {
    OutputFields f(Imu::kType.name);
    if (m.time) f.time("time", m.time);
    f.real("roll", m.roll, 2, -360, 360)
            .real("pitch", m.pitch, 2, -90, 90)
            .real("yaw", m.yaw, 2, -360, 360)
            .real("north acceleration", m.accNorth, 3, -kMaxAcceleration, kMaxAcceleration)
            .real("east acceleration", m.accEast, 3, -kMaxAcceleration, kMaxAcceleration)
            .real("down acceleration", m.accDown, 3, -kMaxAcceleration, kMaxAcceleration);
    return f.build();
}

} // namespace gnss::nvs
