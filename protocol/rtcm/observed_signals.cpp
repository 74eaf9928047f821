#include "rtcm/observed_signals.h"

#include <algorithm>

namespace gnss::rtcm {
namespace {

void addSignal(ObservedSignals &v, std::string_view name) {
    if (!name.empty() &&
        std::find(v.signalNames.begin(), v.signalNames.end(), name) == v.signalNames.end())
        v.signalNames.push_back(name);
}

ObservedSignals viewOf(const MsmHeader &h) {
    ObservedSignals v{h.system, h.epochMs, h.gloDayOfWeek, h.multipleMessage, {}, {}};
    for (const auto id : h.satelliteIds()) v.satellites.push_back(id);
    for (const auto id : h.signalIds()) addSignal(v, msmSignalName(h.system, id));
    return v;
}

ObservedSignals viewOf(const LegacyObservables &o) {
    ObservedSignals v{o.system(), o.epochMs, std::nullopt, o.synchronous, {}, {}};
    for (const LegacySatellite &s : o.satellites) {
        v.satellites.push_back(s.id);
        addSignal(v, legacySignalName(o.system(), 1, s.l1.code));
    }
    for (const LegacySatellite &s : o.satellites)
        if (s.l2) addSignal(v, legacySignalName(o.system(), 2, s.l2->code));
    return v;
}

} // namespace

std::optional<ObservedSignals> observedSignals(const RtcmMessage &m) {
    if (const auto *h = std::get_if<MsmHeader>(&m.body)) return viewOf(*h);
    if (const auto *o = std::get_if<LegacyObservables>(&m.body)) return viewOf(*o);
    return std::nullopt;
}

} // namespace gnss::rtcm
