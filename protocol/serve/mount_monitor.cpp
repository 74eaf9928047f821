// MountMonitor: message types, rates, systems and the station of a served RTCM stream.
#include "serve/mount_monitor.h"

#include "core/wgs84.h"
#include "rtcm/rtcm_messages.h"

#include <cmath>
#include <set>

namespace gnss::serve {

namespace {

// The source table's name of the system an observation message is of; empty for others.
const char *systemOfObservation(unsigned type) {
    if (type >= 1001 && type <= 1004) return "GPS";
    if (type >= 1009 && type <= 1012) return "GLO";
    if (!rtcm::isMsm(type)) return "";
    switch ((type - 1070) / 10) {
    case 0: return "GPS";
    case 1: return "GLO";
    case 2: return "GAL";
    case 3: return "SBAS";
    case 4: return "QZS";
    case 5: return "BDS";
    case 6: return "IRS";
    default: return "";
    }
}

} // namespace

void MountMonitor::frame(const rtcm::RtcmFrame &f, std::int64_t nowMs) {
    ++frames_;
    if (!first_) first_ = nowMs;
    const unsigned type = f.messageNumber();
    seen_[type].push_back(nowMs);
    bytes_.emplace_back(nowMs, f.bytes.size());
    if (type == 1005 || type == 1006) {
        const rtcm::RtcmMessage m = rtcm::decodeMessage(f.payload());
        if (const auto *arp = std::get_if<rtcm::StationArp>(&m.body)) {
            station_ = arp->station;
            auto at = arp->position;
            if (!at) at = wgs84::toGeodetic({arp->x, arp->y, arp->z});
            if (at) {
                latitude_ = at->latDeg;
                longitude_ = at->lonDeg;
            }
        }
    }
    prune(nowMs);
}

void MountMonitor::prune(std::int64_t nowMs) const {
    const std::int64_t from = nowMs - kWindowMs;
    for (auto it = seen_.begin(); it != seen_.end();) {
        auto &times = it->second;
        while (!times.empty() && times.front() < from) times.pop_front();
        it = times.empty() ? seen_.erase(it) : std::next(it);
    }
    while (!bytes_.empty() && bytes_.front().first < from) bytes_.pop_front();
}

std::vector<TypeRate> MountMonitor::rates(std::int64_t nowMs) const {
    prune(nowMs);
    std::vector<TypeRate> out;
    for (const auto &[type, times] : seen_) {
        TypeRate r;
        r.type = type;
        r.count = times.size();
        if (times.size() >= 2)
            r.periodSeconds =
                    double(times.back() - times.front()) / 1000.0 / double(times.size() - 1);
        out.push_back(r);
    }
    return out;
}

std::string MountMonitor::formatDetails(std::int64_t nowMs) const {
    std::string out;
    for (const TypeRate &r : rates(nowMs)) {
        if (r.type == 0) continue;
        if (!out.empty()) out += ',';
        out += std::to_string(r.type);
        if (r.periodSeconds) {
            const long period = std::max(1L, std::lround(*r.periodSeconds));
            out += '(' + std::to_string(period) + ')';
        }
    }
    return out;
}

std::string MountMonitor::navSystem(std::int64_t nowMs) const {
    static const char *const kOrder[] = {"GPS", "GLO", "GAL", "BDS", "QZS", "SBAS", "IRS"};
    std::set<std::string> systems;
    for (const TypeRate &r : rates(nowMs))
        if (*systemOfObservation(r.type)) systems.insert(systemOfObservation(r.type));
    std::string out;
    for (const char *s : kOrder)
        if (systems.count(s)) out += (out.empty() ? "" : "+") + std::string(s);
    return out;
}

int MountMonitor::carrier(std::int64_t nowMs) const {
    int c = 0;
    for (const TypeRate &r : rates(nowMs)) {
        if (rtcm::isMsm(r.type) || r.type == 1003 || r.type == 1004 || r.type == 1011 ||
            r.type == 1012)
            c = 2;
        else if (*systemOfObservation(r.type))
            c = std::max(c, 1);
    }
    return c;
}

int MountMonitor::bitrate(std::int64_t nowMs) const {
    prune(nowMs);
    if (!first_ || nowMs - *first_ < 1000) return 0;
    std::uint64_t total = 0;
    for (const auto &b : bytes_) total += b.second;
    const double seconds = double(std::min<std::int64_t>(nowMs - *first_, kWindowMs)) / 1000.0;
    return static_cast<int>(std::lround(double(total) * 8.0 / seconds));
}

void MountMonitor::describe(ntrip::StreamEntry &e, std::int64_t nowMs) const {
    if (e.format.empty()) e.format = "RTCM 3.3";
    e.formatDetails = formatDetails(nowMs);
    e.carrier = carrier(nowMs);
    e.navSystem = navSystem(nowMs);
    if (latitude_ && longitude_) {
        e.latitude = latitude_;
        e.longitude = longitude_;
    } else if (!e.latitude) {
        e.latitude = 0.0;
        e.longitude = 0.0;
    }
    e.bitrate = bitrate(nowMs);
}

} // namespace gnss::serve
