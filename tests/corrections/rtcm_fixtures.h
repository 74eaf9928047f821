#pragma once
// RTCM fixtures made by our own code: epochs of the simulator's base station.
#include "rtcm_base_station.h"

#include <QByteArray>
#include <QList>

namespace corrections_test {

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
