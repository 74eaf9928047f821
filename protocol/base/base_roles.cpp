#include "base/base_roles.h"

namespace gnss::base {

namespace {

std::string_view valueWith(const SettingDef *def, OptionMeaning meaning) {
    if (!def) return {};
    for (const SettingOption &o : def->options)
        if (o.meaning == meaning) return o.value;
    return {};
}

const SettingDef *portSetting(const Dialect &d, int port,
                              std::initializer_list<SettingRole> roles) {
    for (const SettingDef &def : d.settings)
        for (SettingRole r : roles)
            if (def.role == r && def.port == port) return &def;
    return nullptr;
}

} // namespace

std::string_view BaseRoles::modeValue(OptionMeaning meaning) const {
    return valueWith(mode, meaning);
}

OptionMeaning BaseRoles::modeMeaning(std::string_view value) const {
    for (const SettingOption &o : mode->options)
        if (o.value == value) return o.meaning;
    return OptionMeaning::None;
}

bool BaseRoles::canAverage() const {
    return !modeValue(OptionMeaning::BaseAveraging).empty() && averagingMinutes;
}

std::vector<int> BaseRoles::rtcmPorts() const {
    std::vector<int> ports;
    for (const SettingDef &def : dialect->settings)
        if (def.role == SettingRole::PortProtocol && !valueWith(&def, OptionMeaning::Rtcm3).empty())
            ports.push_back(def.port);
    return ports;
}

const SettingDef *BaseRoles::protocolOf(int port) const {
    return portSetting(*dialect, port, {SettingRole::PortProtocol});
}

const SettingDef *BaseRoles::speedOf(int port) const {
    return portSetting(*dialect, port, {SettingRole::PortSpeed, SettingRole::PortSpeedOf});
}

std::string_view BaseRoles::protocolValue(int port, OptionMeaning meaning) const {
    return valueWith(protocolOf(port), meaning);
}

std::vector<std::string> BaseRoles::keys() const {
    std::vector<std::string> out;
    for (const SettingDef &def : dialect->settings)
        for (const SettingDef *mine : {mode, position, station, rtcmInterval, threshold,
                                       averagingMinutes, averagingInput, nmeaPosition})
            if (mine == &def && def.access != SettingAccess::WriteOnly) out.emplace_back(def.key);
    return out;
}

std::optional<BaseRoles> baseRoles(const Dialect &d) {
    BaseRoles r;
    r.dialect = &d;
    r.mode = findSettingByRole(d.settings, SettingRole::BaseMode);
    r.position = findSettingByRole(d.settings, SettingRole::BasePosition);
    if (!r.mode || !r.position || r.modeValue(OptionMeaning::BaseFixed).empty())
        return std::nullopt;
    r.station = findSettingByRole(d.settings, SettingRole::BaseStationId);
    r.rtcmInterval = findSettingByRole(d.settings, SettingRole::BaseRtcmInterval);
    r.threshold = findSettingByRole(d.settings, SettingRole::BaseThreshold);
    r.averagingMinutes = findSettingByRole(d.settings, SettingRole::BaseAveragingMinutes);
    r.averagingInput = findSettingByRole(d.settings, SettingRole::BaseAveragingInput);
    r.nmeaPosition = findSettingByRole(d.settings, SettingRole::BaseNmeaPosition);
    return r;
}

bool canBeBase(const Dialect &d) {
    return baseRoles(d).has_value();
}

std::string_view meaningName(OptionMeaning m) {
    switch (m) {
    case OptionMeaning::Autonomous: return "autonomous";
    case OptionMeaning::Rover: return "rover";
    case OptionMeaning::BaseFixed: return "base";
    case OptionMeaning::BaseAveraging: return "base_averaging";
    case OptionMeaning::Off: return "off";
    case OptionMeaning::Nmea: return "nmea";
    case OptionMeaning::Rtcm3: return "rtcm3";
    case OptionMeaning::BasePosition: return "base_position";
    case OptionMeaning::OwnPosition: return "own_position";
    case OptionMeaning::None: break;
    }
    return "unknown";
}

} // namespace gnss::base
