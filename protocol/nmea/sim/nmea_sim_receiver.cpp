#include "nmea/sim/nmea_sim_receiver.h"

#include "builtin/dialects.h"
#include "nmea/nmea_messages.h"

namespace gnss::sim {

NmeaReceiver::NmeaReceiver(const SimOptions &options) : Receiver(nmeaDialect(), options) {
    style_.numbering = Numbering::Nmea41;
}

std::vector<std::string> NmeaReceiver::sentencesOf(std::string_view type,
                                                   const SkySnapshot &snap) const {
    const EpochTime t{utcSecondOfDay(), utcDate()};
    if (type == "GGA") return {ggaSentence(snap, t, style_)};
    if (type == "RMC") return {rmcSentence(snap, t, style_)};
    if (type == "VTG") return {vtgSentence(snap, style_)};
    if (type == "ZDA") return {zdaSentence(snap, t, style_)};
    if (type == "GLL") return {gllSentence(snap, t, style_)};
    if (type == "GNS") return {gnsSentence(snap, t, style_)};
    if (type == "GSA") return gsaSentences(snap, style_);
    if (type == "GSV") return gsvSentences(snap, style_);
    return {};
}

void NmeaReceiver::onCommand(const Sentence &s, const Message *decoded, std::string_view) {
    // $--GPQ,GGA: answer with the sentence asked for (from the last epoch).
    const auto *q = decoded ? message_cast<nmea::Query>(*decoded) : nullptr;
    if (!q) return;
    for (const std::string &line : sentencesOf(q->address, lastSnapshot())) reply(s, line);
}

void NmeaReceiver::onEpoch(const SkySnapshot &snap) {
    // GSV every other second: four constellations of GSV every second need more than the
    // 960 bytes a second that 9600 baud carries (receivers at 9600 thin their GSV the same way).
    const bool withGsv = epochs_++ % 2 == 0;
    for (std::string_view type : {"GGA", "GSA", "GSV", "RMC", "VTG", "ZDA"}) {
        if (type == "GSV" && !withGsv) continue;
        for (const std::string &line : sentencesOf(type, snap)) send(line);
    }
}

std::unique_ptr<Receiver> makeNmeaReceiver(const SimOptions &options) {
    return std::make_unique<NmeaReceiver>(options);
}

} // namespace gnss::sim
