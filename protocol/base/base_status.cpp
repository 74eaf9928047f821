#include "base/base_status.h"
#include "base/base_plan.h"

#include <cmath>
#include <cstdlib>

namespace gnss::base {

double distanceBetween(const wgs84::Geodetic &a, const wgs84::Ecef &b) {
    const wgs84::Ecef e = wgs84::toEcef(a);
    return std::hypot(e.x - b.x, e.y - b.y, e.z - b.z);
}

BaseStatus baseStatus(const BaseRoles &roles,
                      const std::function<std::optional<std::string>(std::string_view)> &known,
                      const std::optional<OwnFix> &own) {
    BaseStatus s;
    auto value = [&](const SettingDef *def) -> std::optional<std::string> {
        return def ? known(def->key) : std::nullopt;
    };
    s.mode = value(roles.mode);
    if (s.mode) s.meaning = roles.modeMeaning(*s.mode);
    if (const auto p = value(roles.position)) s.position = ecefOf(*p);
    if (s.position) s.positionGeodetic = wgs84::toGeodetic(*s.position);
    s.station = value(roles.station);
    s.rtcmInterval = value(roles.rtcmInterval);
    s.averagingMinutes = value(roles.averagingMinutes);
    if (const auto n = value(roles.nmeaPosition))
        for (const SettingOption &o : roles.nmeaPosition->options)
            if (o.value == *n) s.nmeaPosition = std::string(meaningName(o.meaning));
    if (const auto t = value(roles.threshold)) {
        char *end = nullptr;
        const double v = std::strtod(t->c_str(), &end);
        if (end && *end == '\0' && std::isfinite(v)) s.threshold = v;
    }
    for (int port : roles.rtcmPorts())
        if (const auto p = value(roles.protocolOf(port)))
            for (const SettingOption &o : roles.protocolOf(port)->options)
                if (o.value == *p) s.ports.emplace_back(port, o.meaning);
    s.own = own;
    if (own && s.position) {
        s.distance = distanceBetween(own->position, *s.position);
        s.beyondThreshold =
                s.isBase() && s.threshold && *s.threshold > 0 && *s.distance > *s.threshold;
    }
    return s;
}

void writeJson(JsonWriter &w, const BaseStatus &s) {
    w.beginObject();
    w.field("mode", s.mode);
    w.field("role", meaningName(s.meaning));
    w.key("position");
    if (s.position) {
        w.beginObject()
                .field("x", s.position->x)
                .field("y", s.position->y)
                .field("z", s.position->z);
        if (s.positionGeodetic)
            w.field("lat", s.positionGeodetic->latDeg)
                    .field("lon", s.positionGeodetic->lonDeg)
                    .field("height", s.positionGeodetic->height);
        w.endObject();
    } else {
        w.null();
    }
    w.field("station", s.station);
    w.field("rtcm_interval", s.rtcmInterval);
    w.field("threshold_m", s.threshold);
    w.field("averaging_minutes", s.averagingMinutes);
    w.field("nmea_position", s.nmeaPosition);
    w.key("ports").beginObject();
    for (const auto &[port, meaning] : s.ports) w.field(std::to_string(port), meaningName(meaning));
    w.endObject();
    w.key("own_fix");
    if (s.own)
        w.beginObject()
                .field("lat", s.own->position.latDeg)
                .field("lon", s.own->position.lonDeg)
                .field("height", s.own->position.height)
                .field("fix", s.own->fix)
                .endObject();
    else
        w.null();
    w.field("distance_m", s.distance);
    w.field("beyond_threshold", s.beyondThreshold);
    w.endObject();
}

} // namespace gnss::base
