#pragma once
// What a receiver is as a base, from its settings as read back and its own fix: its mode and what
// it means, the antenna reference point, station, RTCM interval, the ports known to carry RTCM,
// and how far the set point is from where the receiver finds itself, against the threshold past
// which it would stop sending corrections. For gnss-cli base status and the Base station dock.
#include "base/base_roles.h"
#include "core/json_writer.h"
#include "core/wgs84.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gnss::base {

struct OwnFix {
    wgs84::Geodetic position; // ellipsoidal height when the receiver gives its geoid separation
    std::string fix;          // "3D", "RTK fixed", ...
};

struct BaseStatus {
    std::optional<std::string> mode; // the mode's value
    OptionMeaning meaning = OptionMeaning::None;
    std::optional<wgs84::Ecef> position;
    std::optional<wgs84::Geodetic> positionGeodetic;
    std::optional<std::string> station, rtcmInterval, averagingMinutes, nmeaPosition;
    std::optional<double> threshold;                  // metres
    std::vector<std::pair<int, OptionMeaning>> ports; // ports whose protocol is known
    std::optional<OwnFix> own;
    std::optional<double> distance; // metres from the set point to the own fix
    bool beyondThreshold = false;   // the receiver would not send corrections

    bool isBase() const {
        return meaning == OptionMeaning::BaseFixed || meaning == OptionMeaning::BaseAveraging;
    }
};

BaseStatus baseStatus(const BaseRoles &roles,
                      const std::function<std::optional<std::string>(std::string_view)> &known,
                      const std::optional<OwnFix> &own);

// The distance between two points, metres (through ECEF).
double distanceBetween(const wgs84::Geodetic &a, const wgs84::Ecef &b);

// As one JSON object (gnss-cli base status).
void writeJson(JsonWriter &w, const BaseStatus &s);

} // namespace gnss::base
