#include "logview/play_schedule.h"

namespace gnss::logview {

std::vector<double> playSchedule(std::span<const EpochRecord> records, bool hostTimes,
                                 double speed) {
    std::vector<double> due(records.size(), 0);
    std::int64_t prev = kNoTime;
    double t = 0;
    for (std::size_t i = 0; i < records.size(); ++i) {
        const std::int64_t now = hostTimes ? records[i].hostMs : records[i].utcMs;
        if (now != kNoTime) {
            if (prev != kNoTime && now > prev) t += static_cast<double>(now - prev) / 1000.0;
            prev = now;
        }
        due[i] = t / speed;
    }
    return due;
}

} // namespace gnss::logview
