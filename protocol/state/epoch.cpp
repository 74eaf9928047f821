#include "epoch.h"

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
    for (const auto &s : satellites) {
        w.beginObject()
                .field("system", toString(s.sat.system))
                .field("prn", s.sat.prn)
                .field("signal_id", s.signalId)
                .field("elevation", s.elevation)
                .field("azimuth", s.azimuth)
                .field("snr", s.snr)
                .field("used", s.used)
                .endObject();
    }
    w.endArray().endObject();
}

} // namespace gnss
