#include "corrections/corrections_monitor.h"

#include "corrections/rtcm_message_names.h"

#include <algorithm>
#include <cmath>

namespace gnss::corrections {

namespace {

std::int64_t secondOf(std::int64_t ms) {
    return ms >= 0 ? ms / 1000 : (ms - 999) / 1000;
}

} // namespace

void CorrectionsMonitor::RateCounter::add(std::int64_t nowMs, std::uint64_t n) {
    const std::int64_t s = secondOf(nowMs);
    const auto i = static_cast<std::size_t>(((s % 10) + 10) % 10);
    if (!firstSecond) firstSecond = s;
    if (seconds[i] != s || counts[i] == 0) {
        seconds[i] = s;
        counts[i] = 0;
    }
    counts[i] += n;
}

double CorrectionsMonitor::RateCounter::rate(std::int64_t nowMs) const {
    if (!firstSecond) return 0;
    const std::int64_t s = secondOf(nowMs);
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < counts.size(); ++i)
        if (counts[i] > 0 && seconds[i] > s - 10 && seconds[i] <= s) sum += counts[i];
    // Over the seconds the window has seen so far: a young stream is not under-reported.
    const std::int64_t span = std::clamp<std::int64_t>(s - *firstSecond + 1, 1, 10);
    return static_cast<double>(sum) / static_cast<double>(span);
}

void CorrectionsMonitor::feed(std::string_view bytes, std::int64_t nowMs) {
    if (bytes.empty()) return;
    byteRate_.add(nowMs, bytes.size());
    decoder_.feed(bytes, [&](const rtcm::RtcmMessage &m) { onMessage(m, nowMs); });
}

void CorrectionsMonitor::onMessage(const rtcm::RtcmMessage &m, std::int64_t nowMs) {
    ++messages_;
    lastMessageMs_ = nowMs;
    TypeState &t = types_[m.number];
    ++t.count;
    t.bytes += m.length + 6;
    t.lastMs = nowMs;
    t.rate.add(nowMs, 1);
    if (!m.error.empty()) ++t.decodeErrors;
    if (isObservationMessage(m.number) && m.error.empty()) lastObservationMs_ = nowMs;
    if (const auto *arp = std::get_if<rtcm::StationArp>(&m.body)) {
        BasePosition b;
        b.station = arp->station;
        b.message = m.number;
        b.ecef = {arp->x, arp->y, arp->z};
        b.geodetic = arp->position;
        b.antennaHeight = arp->antennaHeight;
        b.receivedMs = nowMs;
        base_ = b;
    }
}

void CorrectionsMonitor::reset() {
    decoder_ = rtcm::RtcmStreamDecoder();
    types_.clear();
    byteRate_ = RateCounter();
    messages_ = 0;
    lastObservationMs_.reset();
    lastMessageMs_.reset();
    base_.reset();
    history_.clear();
}

MessageTypeStats CorrectionsMonitor::statsOf(unsigned number, const TypeState &t,
                                             std::int64_t nowMs) const {
    MessageTypeStats s;
    s.number = number;
    s.meaning = rtcmMessageMeaning(number);
    s.line = describeRtcmMessage(number);
    s.count = t.count;
    s.bytes = t.bytes;
    s.decodeErrors = t.decodeErrors;
    s.ratePerSecond = t.rate.rate(nowMs);
    s.lastMs = t.lastMs;
    s.ageMs = std::max<std::int64_t>(nowMs - t.lastMs, 0);
    return s;
}

std::vector<MessageTypeStats> CorrectionsMonitor::messageTypes(std::int64_t nowMs) const {
    std::vector<MessageTypeStats> out;
    out.reserve(types_.size());
    for (const auto &[number, t] : types_) out.push_back(statsOf(number, t, nowMs));
    return out;
}

std::optional<MessageTypeStats> CorrectionsMonitor::messageType(unsigned number,
                                                                std::int64_t nowMs) const {
    const auto it = types_.find(number);
    if (it == types_.end()) return std::nullopt;
    return statsOf(number, it->second, nowMs);
}

void CorrectionsMonitor::setRoverPosition(const wgs84::Geodetic &rover) {
    if (!std::isfinite(rover.latDeg) || !std::isfinite(rover.lonDeg) ||
        !std::isfinite(rover.height))
        return rover_.reset();
    rover_ = wgs84::toEcef(rover);
}

std::optional<double> CorrectionsMonitor::baselineMetres() const {
    if (!rover_ || !base_) return std::nullopt;
    const double dx = rover_->x - base_->ecef.x, dy = rover_->y - base_->ecef.y,
                 dz = rover_->z - base_->ecef.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

std::optional<std::int64_t> CorrectionsMonitor::correctionAgeMs(std::int64_t nowMs) const {
    if (!lastObservationMs_) return std::nullopt;
    return std::max<std::int64_t>(nowMs - *lastObservationMs_, 0);
}

std::optional<std::int64_t> CorrectionsMonitor::lastMessageAgeMs(std::int64_t nowMs) const {
    if (!lastMessageMs_) return std::nullopt;
    return std::max<std::int64_t>(nowMs - *lastMessageMs_, 0);
}

void CorrectionsMonitor::sampleAge(std::int64_t nowMs) {
    history_.push_back({nowMs, correctionAgeMs(nowMs)});
    while (history_.size() > kHistoryLength) history_.pop_front();
}

} // namespace gnss::corrections
