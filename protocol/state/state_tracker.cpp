#include "state/state_tracker.h"

#include "nmea/nmea_messages.h"

namespace gnss {

void StateTracker::add(const Sentence &s, const Message &m, const Dialect *ruleDialect,
                       const Callback &onEpoch) {
    auto deliver = [&](const Epoch &e) {
        state_.epoch = e;
        onEpoch(state_);
    };
    if (const auto *h = message_cast<nmea::Hdt>(m)) {
        if (h->heading) state_.rtk.heading = h->heading;
        return;
    }
    if (const auto *g = message_cast<nmea::Gst>(m)) {
        if (g->sdLat) state_.rtk.sdLat = g->sdLat;
        if (g->sdLon) state_.rtk.sdLon = g->sdLon;
        if (g->sdAlt) state_.rtk.sdHeight = g->sdAlt;
        return;
    }
    const Dialect *d = ruleDialect ? ruleDialect : dialect_;
    if (ruleDialect && d->updateState && d->updateState(m, state_)) return;
    epochs_.add(s, m, deliver);
}

void StateTracker::flush(const Callback &onEpoch) {
    epochs_.flush([&](const Epoch &e) {
        state_.epoch = e;
        onEpoch(state_);
    });
}

} // namespace gnss
