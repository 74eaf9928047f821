#pragma once
// One satellite in view as JSON, the same keys wherever a satellite is written (a GSV sentence's
// satellites, an epoch's sky).
#include "core/json_writer.h"
#include "core/satellite.h"

#include <string_view>

namespace gnss {

// Opens the satellite's object with its system, PRN, `idKey`: `id` (what the source numbers it
// by: the id the sentence printed, the signal), elevation, azimuth and SNR; the caller adds any
// further keys and closes it. S has `sat` (SatelliteRef), `elevation`, `azimuth` and `snr`.
template <class S>
JsonWriter &beginSatelliteJson(JsonWriter &w, const S &s, std::string_view idKey, int id) {
    return w.beginObject()
            .field("system", toString(s.sat.system))
            .field("prn", s.sat.prn)
            .field(idKey, id)
            .field("elevation", s.elevation)
            .field("azimuth", s.azimuth)
            .field("snr", s.snr);
}

} // namespace gnss
