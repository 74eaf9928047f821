#pragma once
// The log viewer's tests' yardstick: a plain front-to-back decode of a whole log (StreamDecoder
// + StateTracker, fed in odd-sized chunks), with the receiver state at every epoch.
#include "builtin/simulators.h"
#include "core/stream_decoder.h"
#include "log_generator.h"
#include "scenario_log.h"
#include "state/state_tracker.h"

#include <string>
#include <vector>

namespace gnss::test {

inline std::vector<ReceiverState> frontToBack(std::string_view log, const DialectRegistry &reg,
                                              const DecoderOptions &o = {}) {
    StreamDecoder dec(reg, o);
    StateTracker tracker(dec.dialect());
    std::vector<ReceiverState> states;
    auto onEpoch = [&](const ReceiverState &s) { states.push_back(s); };
    for (std::size_t pos = 0; pos < log.size(); pos += 777)
        dec.feed(log.substr(pos, 777), [&](const SentenceEvent &ev) {
            if (!ev.message) return;
            tracker.setDialect(dec.dialect());
            tracker.add(ev.sentence, *ev.message, ev.dialect, onEpoch);
        });
    dec.finish();
    tracker.flush(onEpoch);
    return states;
}

// What a simulated receiver of `dialect` says in `seconds` (its vendor sentences included),
// after `commands` were sent to it.
inline std::string simulatedLog(const char *dialect, double seconds,
                                const std::string &commands = {}) {
    sim::SimOptions o;
    o.seed = 7;
    auto rx = sim::makeReceiver(dialect, o);
    std::string out;
    if (!commands.empty()) rx->receive(commands);
    for (double t = 0; t < seconds; t += 0.5) {
        rx->advance(0.5);
        out += rx->takeOutput();
    }
    return out;
}

// The logs the tests index, by name.
inline std::string namedLog(const std::string &name) {
    if (name == "scenario") return scenarioLog({});
    if (name == "scenario, no date, midnight") {
        Scenario sc;
        sc.withDate = false;
        sc.startSeconds = 86400 - 200;
        return scenarioLog(sc);
    }
    if (name == "generated 10 Hz") {
        std::string s;
        bench::generateLog(s, 3'000'000);
        return s;
    }
    if (name == "nvs") return simulatedLog("nvs", 900, "$PNVGVER*4E\r\n");
    if (name == "geostar") return simulatedLog("geostar", 900, "$GPSGG,RQUERY*70\r\n");
    if (name == "nemerix") return simulatedLog("nemerix", 900);
    if (name == "nvs then geostar")
        return simulatedLog("nvs", 400, "$PNVGVER*4E\r\n") +
               simulatedLog("geostar", 400, "$GPSGG,RQUERY*70\r\n");
    if (name == "scenario, CR line ends") { // as some loggers write: no LF at all
        std::string s = scenarioLog({}), out;
        for (char c : s)
            if (c != '\n') out += c;
        return out;
    }
    if (name == "junk everywhere") {
        std::string s = scenarioLog({});
        std::string out;
        for (std::size_t i = 0; i < s.size(); i += 997) {
            out += s.substr(i, 997);
            out += std::string("\x00\xFF$GP\x01\r\n\x00", 9);
        }
        return out;
    }
    return {};
}

} // namespace gnss::test
