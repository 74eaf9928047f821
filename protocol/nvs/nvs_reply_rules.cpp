// NVS reply rules, as data (docs/spec-notes.md, "Requests and replies"):
// - PNVGVER is answered by PNVGVER with the identity fields.
// - $ccGPQ,<address> is answered by the sentence named.
// - PNVGNME and PNVGRZA answer with the new settings and then switch.
// - PNVGPPS answers every command with the resulting settings.
// - PNVGCFG answers with a confirming PNVGCFG.
// - PNVGRTK answers with every parameter named in the request.
// - PNVGIDL MODE/ADD echo, REMOVE/CLEAR answer "OK", SHOW answers with one item per station.
// - PNVGRST and PNVGRZB have no reply.
#include "nvs/nvs_reply_rules.h"

#include "core/field_parse.h"

#include <cmath>

namespace gnss::nvs {

namespace {

using V = ReplyVerdict;

V classifyVer(const Sentence &, const Sentence &reply, ReplyProgress &) {
    return reply.address() == "PNVGVER" && reply.fieldCount() >= 5 ? V::Accepted : V::NotMine;
}

V classifyQuery(const Sentence &command, const Sentence &reply, ReplyProgress &) {
    const auto wanted = command.field(0);
    if (reply.address() == wanted) return V::Accepted;
    if (wanted.size() == 3 && !reply.proprietary() && reply.type() == wanted) return V::Accepted;
    return V::NotMine;
}

bool sameNumber(std::string_view a, std::string_view b) {
    double x, y;
    if (parseReal(a, x) && parseReal(b, y)) return std::fabs(x - y) <= 1e-9 * (1 + std::fabs(x));
    return a == b;
}

// The reply is the same sentence with the settings now in force (PNVGNME, PNVGPPS): a field the
// command set that comes back with another value was not taken. Empty command fields (PNVGPPS
// "unchanged") match anything.
V classifyEcho(const Sentence &command, const Sentence &reply, ReplyProgress &) {
    if (reply.address() != command.address() || reply.fieldCount() == 0) return V::NotMine;
    for (std::size_t i = 0; i < command.fieldCount(); ++i)
        if (!command.field(i).empty() && !sameNumber(command.field(i), reply.field(i)))
            return V::Refused;
    return V::Accepted;
}

V classifyRza(const Sentence &command, const Sentence &reply, ReplyProgress &) {
    if (reply.address() != "PNVGRZA") return V::NotMine;
    const bool currentPort = command.field(0) == "0";
    if (!currentPort && reply.field(0) != command.field(0)) return V::NotMine;
    return sameNumber(reply.field(1), command.field(1)) &&
                           sameNumber(reply.field(2), command.field(2))
                   ? V::Accepted
                   : V::Refused;
}

V classifyCfg(const Sentence &, const Sentence &reply, ReplyProgress &) {
    return reply.address() == "PNVGCFG" ? V::Accepted : V::NotMine;
}

// Fields of a PNVGRTK sentence as (name, first value) pairs, names being Table 4's words.
struct Named {
    std::string_view name, value;
    bool hasValue = false;
};
std::vector<Named> rtkParams(const Sentence &s) {
    std::vector<Named> out;
    for (std::size_t i = 0; i < s.fieldCount(); ++i) {
        const auto t = s.field(i);
        if (t.empty()) continue;
        double d;
        const bool value = parseReal(t, d) || t.size() == 1;
        if (!value)
            out.push_back({t, {}, false});
        else if (!out.empty() && !out.back().hasValue)
            out.back().value = t, out.back().hasValue = true;
    }
    return out;
}

V classifyRtk(const Sentence &command, const Sentence &reply, ReplyProgress &) {
    if (reply.address() != "PNVGRTK") return V::NotMine;
    const auto asked = rtkParams(command);
    const auto got = rtkParams(reply);
    int found = 0;
    bool differs = false;
    for (const auto &a : asked) {
        for (const auto &g : got) {
            if (g.name != a.name) continue;
            ++found;
            // A set parameter whose reported value differs was not taken (BASEXYZ/BASEBLH are
            // compared on their first value; BASEBLH may come back in the other form).
            if (a.hasValue && g.hasValue && a.name != "BASEBLH" && !sameNumber(a.value, g.value))
                differs = true;
            break;
        }
    }
    if (found == 0) return V::NotMine; // e.g. the answer to another PNVGRTK in flight
    if (found < static_cast<int>(asked.size()) || differs) return V::Refused;
    return V::Accepted;
}

V classifyIdl(const Sentence &command, const Sentence &reply, ReplyProgress &progress) {
    if (reply.address() != "PNVGIDL") return V::NotMine;
    const auto sub = command.field(0);
    const auto rsub = reply.field(0);
    std::int64_t n;
    if (sub == "SHOW") {
        if (!parseInt(rsub, n)) return V::NotMine;
        progress.expected = static_cast<int>(n);
        ++progress.received;
        if (n == 0) return V::Accepted; // an empty list
        return progress.received >= progress.expected ? V::Accepted : V::Partial;
    }
    if (rsub != sub) return V::NotMine;
    if (sub == "REMOVE" || sub == "CLEAR") return reply.field(1) == "OK" ? V::Accepted : V::Refused;
    if (sub == "MODE")
        return sameNumber(reply.field(1), command.field(1)) ? V::Accepted : V::Refused;
    return V::Accepted; // ADD echoes the station added
}

constexpr ReplyRule kRules[] = {
        {"PNVGVER", "", classifyVer, 1000, 2, CommandEffect::None,
         "$PNVGVER,NVS,<RTK|RTA>,<RTK FW>,CSM24,<CSM FW>"},
        {"GPGPQ", "", classifyQuery, 1000, 2, CommandEffect::None,
         "the sentence named in the query ($GPGPQ,PNVGTST -> $PNVGTST,...)"},
        {"PNVGNME", "", classifyEcho, 1000, 2, CommandEffect::ChangesOutput,
         "$PNVGNME with the new settings; the receiver then switches to them"},
        {"PNVGRST", "", nullptr, 1000, 0, CommandEffect::ResetsReceiver,
         "no reply: the receiver restarts (F cold, W warm)"},
        {"PNVGRZA", "", classifyRza, 1000, 1, CommandEffect::ChangesBaud,
         "$PNVGRZA,<port>,<baud>,<protocol> with the new settings, then the port switches within "
         "100 ms; other values than asked = refused"},
        {"PNVGRZB", "", nullptr, 1000, 0, CommandEffect::ChangesOutput,
         "no reply: the listed messages start (or the list is cleared)"},
        {"PNVGCFG", "R", classifyCfg, 3000, 1, CommandEffect::ResetsReceiver,
         "a confirming $PNVGCFG; the settings are erased and the receiver restarts"},
        {"PNVGCFG", "", classifyCfg, 3000, 1, CommandEffect::None,
         "a confirming $PNVGCFG once the settings are saved (W) or erased (E)"},
        {"PNVGPPS", "", classifyEcho, 1000, 2, CommandEffect::None,
         "$PNVGPPS with the resulting time pulse settings"},
        {"PNVGRTK", "", classifyRtk, 1000, 2, CommandEffect::None,
         "$PNVGRTK with every parameter named in the request and its value; a parameter "
         "missing or with another value than set = refused"},
        {"PNVGIDL", "SHOW", classifyIdl, 2000, 1, CommandEffect::None,
         "$PNVGIDL,<count>,<index>,<id>,<icb> per stored station (count items)"},
        {"PNVGIDL", "MODE", classifyIdl, 1000, 2, CommandEffect::None, "$PNVGIDL,MODE,<mode> echo"},
        {"PNVGIDL", "ADD", classifyIdl, 1000, 1, CommandEffect::None,
         "$PNVGIDL,ADD,<id>,<icb> with the station added"},
        {"PNVGIDL", "REMOVE", classifyIdl, 1000, 1, CommandEffect::None,
         "$PNVGIDL,REMOVE,OK; anything else = refused"},
        {"PNVGIDL", "CLEAR", classifyIdl, 1000, 1, CommandEffect::None,
         "$PNVGIDL,CLEAR,OK; anything else = refused"},
};

} // namespace

std::span<const ReplyRule> replyRules() {
    return kRules;
}

} // namespace gnss::nvs
