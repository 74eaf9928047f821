#include "base/base_plan.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace gnss::base {

namespace {

void put(BasePlan &plan, const SettingDef *def, std::string value, const char *option) {
    if (!plan.ok()) return;
    if (!def) {
        plan.error = std::string(option) + ": this receiver has no such setting";
        return;
    }
    if (const Refusal r = validateSetting(*def, value); !r.text.empty()) {
        plan.error = std::string(option) + ": " + r.text;
        return;
    }
    plan.values.push_back({std::string(def->key), std::move(value)});
}

} // namespace

std::string ecefText(const wgs84::Ecef &p) {
    char text[96];
    std::snprintf(text, sizeof text, "%.3f,%.3f,%.3f", p.x, p.y, p.z);
    return text;
}

std::optional<wgs84::Ecef> ecefOf(std::string_view text) {
    double v[3];
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = i < 2 ? text.find(',') : text.size();
        if (comma == std::string_view::npos) return std::nullopt;
        std::string_view part = text.substr(0, comma);
        while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
        while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
        const auto r = std::from_chars(part.data(), part.data() + part.size(), v[i]);
        if (part.empty() || r.ec != std::errc() || r.ptr != part.data() + part.size() ||
            !std::isfinite(v[i]))
            return std::nullopt;
        text.remove_prefix(std::min(text.size(), comma + 1));
    }
    return wgs84::Ecef{v[0], v[1], v[2]};
}

wgs84::Ecef raised(const wgs84::Ecef &mark, double height) {
    if (height == 0) return mark;
    auto g = wgs84::toGeodetic(mark);
    if (!g) return mark;
    g->height += height;
    return wgs84::toEcef(*g);
}

bool nearTheEllipsoid(const wgs84::Ecef &p) {
    const auto g = wgs84::toGeodetic(p);
    return g && std::abs(g->height) <= 100000;
}

BasePlan planBase(const BaseRoles &roles, const BaseRequest &request,
                  const std::function<std::optional<std::string>(std::string_view)> &known) {
    BasePlan plan;
    if (request.kind == BaseRequest::Kind::Fixed) {
        if (!request.position) {
            plan.error = "a base needs its position (--ecef, --llh or --site)";
            return plan;
        }
        if (!nearTheEllipsoid(*request.position)) {
            plan.error = "the position " + ecefText(*request.position) +
                         " is not near the Earth's surface (X,Y,Z are metres, ECEF)";
            return plan;
        }
        put(plan, roles.mode, std::string(roles.modeValue(OptionMeaning::BaseFixed)), "mode");
        put(plan, roles.position, ecefText(*request.position), "position");
    } else {
        if (!roles.canAverage()) {
            plan.error = "--by-receiver: this receiver does not average its own position";
            return plan;
        }
        put(plan, roles.mode, std::string(roles.modeValue(OptionMeaning::BaseAveraging)), "mode");
        if (request.averagingMinutes)
            put(plan, roles.averagingMinutes, std::to_string(*request.averagingMinutes),
                "--minutes");
        if (request.averagingInput)
            put(plan, roles.averagingInput, *request.averagingInput, "--input");
    }
    if (request.station) put(plan, roles.station, std::to_string(*request.station), "--station");
    if (request.rtcmInterval)
        put(plan, roles.rtcmInterval, std::to_string(*request.rtcmInterval), "--rtcm-interval");
    if (request.rtcmPort && plan.ok()) {
        const int port = *request.rtcmPort;
        const auto ports = roles.rtcmPorts();
        const std::string_view rtcm = roles.protocolValue(port, OptionMeaning::Rtcm3);
        if (std::find(ports.begin(), ports.end(), port) == ports.end() || rtcm.empty()) {
            plan.error = "--rtcm-port: no port " + std::to_string(port) + " can carry RTCM 3 (";
            for (std::size_t i = 0; i < ports.size(); ++i)
                plan.error += (i ? ", " : "") + std::to_string(ports[i]);
            plan.error += ports.empty() ? "none)" : " can)";
            plan.values.clear();
            return plan;
        }
        put(plan, roles.protocolOf(port), std::string(rtcm), "--rtcm-port");
        if (const SettingDef *speed = roles.speedOf(port)) {
            std::string baud =
                    request.rtcmPortSpeed
                            ? std::to_string(*request.rtcmPortSpeed)
                            : known(speed->key).value_or(std::string(speed->defaultValue));
            put(plan, speed, baud, "--rtcm-baud");
        }
    }
    // The schema's order: the engine sorts commands by their effects, the reader sees the rows.
    std::stable_sort(plan.values.begin(), plan.values.end(),
                     [&](const KeyValue &a, const KeyValue &b) {
                         auto index = [&](const std::string &key) {
                             const auto &s = roles.dialect->settings;
                             for (std::size_t i = 0; i < s.size(); ++i)
                                 if (s[i].key == key) return i;
                             return s.size();
                         };
                         return index(a.key) < index(b.key);
                     });
    if (!plan.ok()) plan.values.clear();
    return plan;
}

} // namespace gnss::base
