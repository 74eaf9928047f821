// The simulator's receivers by dialect id: one line per receiver family.
#include "geostar_receiver.h"
#include "nmea_receiver.h"
#include "nvs_receiver.h"
#include "receiver.h"

namespace gnss::sim {

std::vector<std::string_view> simulatedDialects() {
    return {"nvs", "geostar", "nmea"};
}

std::unique_ptr<Receiver> makeReceiver(std::string_view dialect, const SimOptions &options) {
    if (dialect == "nvs") return std::make_unique<NvsReceiver>(options);
    if (dialect == "geostar") return std::make_unique<GeoStarReceiver>(options);
    if (dialect == "nmea") return std::make_unique<NmeaReceiver>(options);
    return nullptr;
}

} // namespace gnss::sim
