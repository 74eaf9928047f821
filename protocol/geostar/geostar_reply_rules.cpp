// GeoS-5 reply rules. The spec (sections 3.11, 3.12, 4) names only two answers: RQUERY and NQUERY
// are answered by their replies. No other command is acknowledged: a set command is confirmed by
// the RQUERY/NQUERY reading that follows it (encodeSettings appends that query), restarts, port
// speed changes and SWPROT are not answered at all.
#include "geostar/geostar_reply_rules.h"

#include "geostar/geostar_commands.h"

#include <string>
#include <vector>

namespace gnss::geostar {
namespace {

bool isReply(const Sentence &reply, std::string_view name) {
    return reply.address() == kAddress && reply.field(0) == name && reply.fieldCount() > 1;
}

ReplyVerdict classifyRquery(const Sentence &, const Sentence &reply, ReplyProgress &p) {
    if (!isReply(reply, "RQUERY")) return ReplyVerdict::NotMine;
    p.received = p.expected = 1;
    return ReplyVerdict::Accepted;
}

ReplyVerdict classifyNquery(const Sentence &, const Sentence &reply, ReplyProgress &p) {
    if (!isReply(reply, "NQUERY")) return ReplyVerdict::NotMine;
    p.received = p.expected = 1;
    return ReplyVerdict::Accepted;
}

std::string describe(const CommandDef &c) {
    if (c.text == "RQUERY")
        return "Answered by $GPSGG,RQUERY,GEOS-5,V.x.xxx,ddmmyy,<status>,<config 1>,<config 2>";
    if (c.text == "NQUERY")
        return "Answered by $GPSGG,NQUERY,<port>,<rate>,<NMEA version>,<10 message codes>";
    std::string d = "No reply. ";
    switch (c.effect) {
    case CommandEffect::ResetsReceiver: d += "The receiver restarts."; break;
    case CommandEffect::ChangesBaud:
        d += "The port settings change at once; continue at the new settings.";
        break;
    case CommandEffect::ChangesProtocol:
        d += "The port leaves NMEA for the binary protocol.";
        break;
    case CommandEffect::ChangesOutput: d += "The output changes."; break;
    case CommandEffect::None: break;
    }
    if (!c.confirmedBy.empty())
        d += " Confirmed by the next $GPSGG," + std::string(c.confirmedBy) + " reading.";
    else if (c.effect == CommandEffect::None || c.effect == CommandEffect::ChangesOutput)
        d += " The receiver reports nothing that would confirm it.";
    if (c.text == "PSM ON" || c.text == "PSMOFF")
        d += " The receiver sends one RQUERY reply when it enters or leaves sleep.";
    return d;
}

struct Rules {
    std::vector<std::string> descriptions;
    std::vector<ReplyRule> rules;
    Rules() {
        const auto cmds = commands();
        descriptions.reserve(cmds.size()); // string_views below point into these
        for (const CommandDef &c : cmds) {
            descriptions.push_back(describe(c));
            ReplyRule r;
            r.commandAddress = kAddress;
            r.firstField = c.text;
            r.classify = c.text == "RQUERY"   ? classifyRquery
                         : c.text == "NQUERY" ? classifyNquery
                                              : nullptr;
            r.timeoutMs = 1000;
            r.retries = r.classify ? 2 : 0;
            r.effect = c.effect;
            r.description = descriptions.back();
            rules.push_back(r);
        }
    }
};

} // namespace

std::span<const ReplyRule> replyRules() {
    static const Rules r;
    return r.rules;
}

} // namespace gnss::geostar
