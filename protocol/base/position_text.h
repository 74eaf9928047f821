#pragma once
// Coordinates as users type them, for a base's position and a site:
//   an angle: decimal degrees ("55.7512", "-37.5"), degrees and minutes ("55 45.072",
//   "55°45.072'"), or degrees, minutes and seconds ("55°45'04.32\"", "55 45 4.32", "55:45:4.32",
//   "55d45m4.32s"); a capital hemisphere letter before or after (N S for a latitude, E W for a
//   longitude) instead of a sign;
//   a geodetic point "LAT,LON,HEIGHT" (height in metres);
//   an ECEF point "X,Y,Z" in metres (base_plan.h: ecefOf).
// Every refusal says what was wrong ("latitude: minutes 61 are not below 60").
#include "core/wgs84.h"

#include <optional>
#include <string>
#include <string_view>

namespace gnss::base {

enum class Axis { Latitude, Longitude };

std::optional<double> parseAngle(std::string_view text, Axis axis, std::string &error);
std::optional<wgs84::Geodetic> parseGeodetic(std::string_view text, std::string &error);

} // namespace gnss::base
