#include "logview/log_events.h"

#include "core/dialect_registry.h"
#include "logview/log_time.h"

#include <cstdio>

namespace gnss::logview {
namespace {

std::string dialectName(const DialectRegistry &registry, std::uint8_t index) {
    const auto all = registry.dialects();
    if (index == 0 || index > all.size()) return "unknown";
    return std::string(all[index - 1]->displayName);
}

std::string seconds(double s) {
    char b[32];
    std::snprintf(b, sizeof b, s < 10 ? "%.1f s" : "%.0f s", s);
    return b;
}

// A text field, RFC 4180 quoted when needed. Texts come from the log (a recording's index says
// why its link dropped): one a spreadsheet would take for a formula ('=', '+', '-', '@', a tab
// or CR first) gets a "'" in front, so opening the file never runs what a log said.
std::string csvField(std::string_view s) {
    const bool formula =
            !s.empty() && std::string_view("=+-@\t\r").find(s.front()) != std::string_view::npos;
    if (!formula && s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
    std::string out = formula ? "\"'" : "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

} // namespace

std::string_view toString(EventKind k) {
    switch (k) {
    case EventKind::FixChange: return "fix";
    case EventKind::Gap: return "gap";
    case EventKind::LinkGap: return "link";
    case EventKind::ChecksumErrors: return "checksum";
    case EventKind::TimeJump: return "time_jump";
    case EventKind::DialectChange: return "dialect";
    case EventKind::TimeMark: return "time_mark";
    case EventKind::Jamming: return "jamming";
    case EventKind::BaseStation: return "base_station";
    }
    return "";
}

void collectEvents(std::span<const EpochRecord> records, std::size_t from, std::size_t to,
                   const DialectRegistry &registry, const HostTimes *host, EventState &st,
                   std::vector<LogEvent> &out) {
    for (std::size_t i = from; i < to && i < records.size(); ++i) {
        const EpochRecord &r = records[i];
        auto add = [&](EventKind kind, std::string text) {
            LogEvent e;
            e.epoch = i;
            e.offset = r.offset;
            e.utcMs = r.utcMs;
            e.hostMs = r.hostMs;
            e.dated = r.has(kDateKnown);
            e.kind = kind;
            e.text = std::move(text);
            out.push_back(std::move(e));
        };
        if (r.has(kLinkGap) && host) {
            const auto &gaps = host->gaps();
            while (st.nextLinkGap < gaps.size() && gaps[st.nextLinkGap].offset <= r.offset)
                add(EventKind::LinkGap, gaps[st.nextLinkGap++].text);
        }
        if (r.has(kGapBefore) && st.prevTimeMs != kNoTime)
            add(EventKind::Gap, "no epochs for " + seconds((r.utcMs - st.prevTimeMs) / 1000.0));
        if (r.has(kTimeBack))
            add(EventKind::TimeJump,
                "time went back from " + (st.havePrev ? formatTime(st.prev) : std::string("?")) +
                        " to " + formatTime(r) + " (receiver reset?)");
        if (r.has(kDialectChange)) {
            std::string text = dialectName(registry, r.dialect) + " sentences";
            if (st.havePrev && st.prev.dialect != 0 && st.prev.dialect != r.dialect)
                text += " (after " + dialectName(registry, st.prev.dialect) + ")";
            add(EventKind::DialectChange, text);
        }
        if (r.has(kFixChange) && st.havePrev)
            add(EventKind::FixChange, std::string(fixWords(st.prev.fixType())) + " → " +
                                              std::string(fixWords(r.fixType())));
        if (r.has(kStationChange)) {
            std::string text = "base station " + std::to_string(r.station);
            if (st.havePrev && st.prev.station >= 0)
                text += " (was " + std::to_string(st.prev.station) + ")";
            add(EventKind::BaseStation, text);
        }
        if (r.has(kJammingChange))
            add(EventKind::Jamming, r.jamming == 2 ? "jamming detected" : "jamming cleared");
        if (r.has(kTimeMark)) add(EventKind::TimeMark, "time mark");
        // Checksum errors in consecutive epochs are one burst.
        if (r.has(kChecksumErrors)) {
            if (st.burstEvent == static_cast<std::size_t>(-1) || st.burstEvent >= out.size()) {
                add(EventKind::ChecksumErrors, {});
                st.burstEvent = out.size() - 1;
                st.burstErrors = st.burstEpochs = 0;
            }
            st.burstErrors += r.checksumErrors;
            ++st.burstEpochs;
            out[st.burstEvent].text = std::to_string(st.burstErrors) +
                                      (st.burstErrors == 1 ? " sentence" : " sentences") +
                                      " with a wrong checksum in " +
                                      std::to_string(st.burstEpochs) +
                                      (st.burstEpochs == 1 ? " epoch" : " epochs");
        } else {
            st.burstEvent = static_cast<std::size_t>(-1);
        }
        if (r.hasTime()) st.prevTimeMs = r.utcMs;
        st.prev = r;
        st.havePrev = true;
    }
}

std::string eventsCsv(std::span<const LogEvent> events) {
    std::string out = "epoch,time,host_time,kind,text\r\n";
    for (const LogEvent &e : events) {
        EpochRecord r;
        r.utcMs = e.utcMs;
        if (e.dated) r.flags = kDateKnown;
        out += std::to_string(e.epoch) + "," + formatTime(r) + "," +
               (e.hostMs != kNoTime ? formatUtcMs(e.hostMs) : std::string()) + "," +
               std::string(toString(e.kind)) + "," + csvField(e.text) + "\r\n";
    }
    return out;
}

} // namespace gnss::logview
