#pragma once
// What setting up a base comes to: the settings (by their roles) that make the receiver a base at
// a position, or a base that averages its own position first, with its station id, RTCM interval
// and the port that carries the RTCM. The settings engine then applies them, reads them back and
// reports each as verified or not; nothing here sends anything.
#include "base/base_roles.h"
#include "core/wgs84.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gnss::base {

struct BaseRequest {
    enum class Kind {
        Fixed,     // a base at `position`
        Averaging, // the receiver averages its own position for `averagingMinutes`, then is a base
    };
    Kind kind = Kind::Fixed;
    std::optional<wgs84::Ecef> position; // Fixed: the antenna reference point
    std::optional<int> station;          // RTCM station id
    std::optional<int> rtcmInterval;     // seconds between observables (a value of the schema)
    std::optional<int> rtcmPort;         // the port to carry RTCM 3 (the vendor's number)
    std::optional<int> rtcmPortSpeed;    // its speed; default: the known one, else the schema's
    std::optional<int> averagingMinutes; // Averaging
    std::optional<std::string> averagingInput; // Averaging: a value of the input setting
};

struct BasePlan {
    std::vector<KeyValue> values; // in the schema's order
    std::string error;            // why nothing may be sent (names the option and its range)
    bool ok() const { return error.empty(); }
};

// The settings for `request`. `known` gives a setting's value as the receiver has it (nullopt
// when unknown): a port's speed goes with its protocol in one command.
BasePlan planBase(const BaseRoles &roles, const BaseRequest &request,
                  const std::function<std::optional<std::string>(std::string_view key)> &known);

// BasePosition's text for an ECEF point ("X,Y,Z", millimetres), and back.
std::string ecefText(const wgs84::Ecef &p);
std::optional<wgs84::Ecef> ecefOf(std::string_view text);

// The antenna reference point `height` metres above the mark `mark`, along the ellipsoid's
// normal.
wgs84::Ecef raised(const wgs84::Ecef &mark, double height);

// A point within 100 km of the ellipsoid, as an antenna is: X,Y,Z typed in kilometres, or a
// latitude typed into X, is not.
bool nearTheEllipsoid(const wgs84::Ecef &p);

} // namespace gnss::base
