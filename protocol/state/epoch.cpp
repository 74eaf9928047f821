#include "state/epoch.h"

#include "core/satellite_json.h"

namespace gnss {

std::string Epoch::timeText() const {
    if (!time) return {};
    if (date) return date->toString() + "T" + time->toString(3) + "Z";
    return time->toString(3);
}

void Epoch::writeJson(JsonWriter &w) const {
    w.beginObject();
    if (time)
        w.field("time", timeText());
    else
        w.key("time").null();
    w.field("fix", toString(fix));
    if (!fixNote.empty()) w.field("fix_note", fixNote);
    w.field("lat", lat)
            .field("lon", lon)
            .field("alt_msl", altMsl)
            .field("alt_ellipsoid", altEllipsoid())
            .field("sats_used", satsUsed)
            .field("hdop", hdop)
            .field("pdop", pdop)
            .field("vdop", vdop)
            .field("sog_knots", sogKnots)
            .field("cog", cog)
            .field("dgps_age", dgpsAge)
            .field("dgps_station", dgpsStation)
            .key("satellites")
            .beginArray();
    for (const auto &s : satellites)
        beginSatelliteJson(w, s, "signal_id", s.signalId).field("used", s.used).endObject();
    w.endArray().endObject();
}

} // namespace gnss
