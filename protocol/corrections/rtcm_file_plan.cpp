#include "corrections/rtcm_file_plan.h"

#include "rtcm/rtcm_framer.h"
#include "rtcm/rtcm_messages.h"

#include <algorithm>
#include <array>
#include <optional>

namespace gnss::corrections {

namespace {

struct FoundFrame {
    std::size_t begin, end;
    unsigned number;
    std::optional<std::uint32_t> epochMs; // MSM only
    rtcm::System system = rtcm::System::Gps;
};

std::vector<FoundFrame> findFrames(std::string_view file, std::size_t &crcFailures) {
    std::vector<FoundFrame> out;
    rtcm::RtcmFramer framer;
    std::size_t searchFrom = 0;
    auto keep = [&](const rtcm::RtcmFrame &f) {
        // Frames found in one feed of the whole file point into it; should one come from the
        // framer's own buffer, it is looked up in the file instead.
        const auto *p = reinterpret_cast<const char *>(f.bytes.data());
        std::size_t begin = 0;
        if (p >= file.data() && p + f.bytes.size() <= file.data() + file.size()) {
            begin = static_cast<std::size_t>(p - file.data());
        } else {
            begin = file.find(std::string_view(p, f.bytes.size()), searchFrom);
            if (begin == std::string_view::npos) return;
        }
        FoundFrame ff{begin, begin + f.bytes.size(), f.messageNumber(), std::nullopt};
        if (rtcm::isMsm(ff.number)) {
            const rtcm::RtcmMessage m = rtcm::decodeMessage(f.payload());
            if (const auto *h = std::get_if<rtcm::MsmHeader>(&m.body)) {
                ff.epochMs = h->epochMs;
                ff.system = h->system;
            }
        }
        searchFrom = ff.end;
        out.push_back(ff);
    };
    framer.feed(file, keep);
    framer.finish(keep);
    crcFailures = static_cast<std::size_t>(framer.stats().crcFailures);
    return out;
}

std::int64_t periodOf(rtcm::System s) {
    return s == rtcm::System::Glonass ? 86400000 : 604800000; // time of day / of week
}

} // namespace

PlaybackPlan planPlayback(std::string_view file) {
    PlaybackPlan plan;
    const std::vector<FoundFrame> frames = findFrames(file, plan.crcFailures);
    plan.frames = frames.size();
    const bool anyMsm = std::any_of(frames.begin(), frames.end(),
                                    [](const FoundFrame &f) { return f.epochMs.has_value(); });
    const bool anyStation = std::any_of(frames.begin(), frames.end(), [](const FoundFrame &f) {
        return f.number == 1005 || f.number == 1006;
    });
    plan.timing = anyMsm       ? PlaybackPlan::Timing::Msm
                  : anyStation ? PlaybackPlan::Timing::StationMessages
                               : PlaybackPlan::Timing::AllAtOnce;

    // Per system: its last epoch time and the playback time that epoch was given.
    std::array<std::optional<std::uint32_t>, 8> lastEpoch{};
    std::array<std::int64_t, 8> lastTime{};
    std::int64_t groupTime = 0;
    bool stationSeen = false;
    for (const FoundFrame &f : frames) {
        std::int64_t at = groupTime;
        if (plan.timing == PlaybackPlan::Timing::Msm && f.epochMs) {
            const auto sys = static_cast<std::size_t>(f.system);
            if (lastEpoch[sys]) {
                const std::int64_t period = periodOf(f.system);
                std::int64_t step =
                        (std::int64_t(*f.epochMs) - std::int64_t(*lastEpoch[sys]) + period) %
                        period;
                if (step > period / 2) step = 1000; // backwards: files joined together
                at = lastTime[sys] + std::min(step, kMaxPlaybackGapMs);
            }
            lastEpoch[sys] = *f.epochMs;
            lastTime[sys] = at;
        } else if (plan.timing == PlaybackPlan::Timing::StationMessages &&
                   (f.number == 1005 || f.number == 1006)) {
            if (stationSeen) at = groupTime + 1000;
            stationSeen = true;
        }
        if (plan.groups.empty()) {
            plan.groups.push_back({0, 0, at, 0}); // junk before the first frame goes with it
            groupTime = at;
        } else if (at > groupTime) { // a later epoch; a lagging system joins the current one
            const std::size_t begin = plan.groups.back().end;
            plan.groups.push_back({begin, begin, at, 0});
            groupTime = at;
        }
        plan.groups.back().end = f.end;
        ++plan.groups.back().frames;
    }
    if (plan.groups.empty() && !file.empty()) plan.groups.push_back({0, file.size(), 0, 0});
    if (!plan.groups.empty()) plan.groups.back().end = file.size(); // trailing bytes go last
    return plan;
}

} // namespace gnss::corrections
