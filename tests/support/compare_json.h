#pragma once
// Reading gnss-cli compare --json: a receiver's mean difference on one axis (metres) and its mean
// C/N0 difference for one constellation (dB); 0 when the report has none.
#include <QJsonObject>

namespace gnss::test {

inline double compareMean(const QJsonObject &receiver, const char *axis) {
    return receiver["difference_m"].toObject()[axis].toObject()["mean"].toDouble();
}

inline double compareCn0(const QJsonObject &receiver, const char *system) {
    return receiver["cn0_db"]
            .toObject()["per_constellation"]
            .toObject()[system]
            .toObject()["mean"]
            .toDouble();
}

} // namespace gnss::test
