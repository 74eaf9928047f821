#pragma once
// RTCM fixtures made by our own code: epochs of the simulator's base station.
#include "sim/rtcm_base_station.h"

#include <QByteArray>
#include <QList>

#include <string_view>

namespace corrections_test {

// The bytes of `b`, as the corrections classes read them.
inline std::string_view view(const QByteArray &b) {
    return {b.constData(), std::size_t(b.size())};
}

// `count` one-second epochs of the simulated base (MSM4 GPS and GLONASS, 1005, 1230 at 0).
inline QList<QByteArray> baseEpochs(int count, unsigned seed = 1) {
    gnss::sim::BaseStationConfig c;
    c.seed = seed;
    gnss::sim::RtcmBaseStation base(c);
    QList<QByteArray> out;
    for (int i = 0; i < count; ++i) {
        base.advance(i == 0 ? 0.0 : 1.0);
        out.append(QByteArray::fromStdString(base.takeOutput()));
    }
    return out;
}

} // namespace corrections_test
