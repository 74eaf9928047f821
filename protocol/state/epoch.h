#pragma once
// Epoch: the receiver's state at one navigation fix time, assembled from the sentences of that
// epoch (GGA/RMC/GNS/GLL/ZDA for time and position, GSA for DOPs and used satellites, GSV groups
// for the sky).
#include "core/field_types.h"
#include "core/fix_type.h"
#include "core/json_writer.h"
#include "core/satellite.h"
#include "core/wgs84.h"

#include <optional>
#include <string>
#include <vector>

namespace gnss {

struct SatelliteInView {
    SatelliteRef sat;
    int signalId = 0; // NMEA 4.10+ signal id; 0 when the receiver does not say
    std::optional<int> elevation, azimuth, snr;
    bool used = false;
    bool operator==(const SatelliteInView &) const = default;
};

struct Epoch {
    std::optional<TimeOfDay> time;
    std::optional<Date> date;
    FixType fix = FixType::None;
    std::string fixNote; // vendor nuance shown beside the badge ("GeoPath")
    std::optional<double> lat, lon;
    std::optional<double> altMsl, geoidSep;
    std::optional<double> sogKnots, cog;
    std::optional<double> pdop, hdop, vdop;
    std::optional<int> satsUsed;
    std::optional<double> dgpsAge;
    std::optional<int> dgpsStation;
    std::vector<SatelliteInView> satellites;
    int sentences = 0; // sentences that contributed
    bool operator==(const Epoch &) const = default;

    std::optional<double> altEllipsoid() const {
        if (altMsl && geoidSep) return *altMsl + *geoidSep;
        return std::nullopt;
    }
    // The fix's position: its height above the ellipsoid, or above sea level when the receiver
    // gives no geoid separation (0 with no height at all); none without a fix.
    std::optional<wgs84::Geodetic> position() const {
        if (fix == FixType::None || !lat || !lon) return std::nullopt;
        return wgs84::Geodetic{*lat, *lon, altEllipsoid().value_or(altMsl.value_or(0))};
    }
    // ISO 8601 UTC ("2018-05-31T15:35:56.000Z") when the date is known, else "hh:mm:ss.sss".
    std::string timeText() const;
    void writeJson(JsonWriter &w) const;
};

} // namespace gnss
