#include "config/apply_verdicts.h"

#include "config/setting_values.h"
#include "core/sentence_builder.h"

#include <algorithm>

namespace gnss::config {

bool succeeded(const link::CommandResult &r) {
    return r.outcome == link::CommandOutcome::Accepted || r.outcome == link::CommandOutcome::Sent;
}

bool anyLinkLost(const QList<link::CommandResult> &commands) {
    return std::any_of(commands.begin(), commands.end(), [](const link::CommandResult &c) {
        return c.outcome == link::CommandOutcome::LinkLost;
    });
}

CommandFate fateOf(const std::vector<std::string> &sentences,
                   const QList<link::CommandResult> &commands) {
    bool all = !sentences.empty(), anyGone = false, inFlight = false, lostUnsent = false;
    for (const std::string &s : sentences) {
        std::string why;
        std::string line = completeSentence(s, why);
        if (line.empty()) line = s;
        const QString sentence = QString::fromStdString(line);
        const auto r =
                std::find_if(commands.begin(), commands.end(),
                             [&](const link::CommandResult &c) { return c.sentence == sentence; });
        const bool ok = r != commands.end() && succeeded(*r);
        all = all && ok;
        anyGone = anyGone || ok;
        if (r == commands.end()) continue;
        const bool lost = r->outcome == link::CommandOutcome::LinkLost;
        inFlight = inFlight || (lost && r->attempts > 0);
        lostUnsent = lostUnsent || (lost && r->attempts == 0);
    }
    if (all) return CommandFate::Taken;
    if (inFlight || (anyGone && lostUnsent)) return CommandFate::Unconfirmed;
    return CommandFate::NotSent;
}

bool isGood(Verdict v) {
    return v == Verdict::Verified || v == Verdict::Echoed || v == Verdict::WrittenUnverified;
}

namespace {
Verdict compared(const SettingDef &def, const std::string &wanted, const std::string &reported) {
    if (!sameValue(def, wanted, reported)) return Verdict::NotTaken;
    // A write-only setting's value comes from its command's answer, never from a read-back.
    return isReadable(def) ? Verdict::Verified : Verdict::Echoed;
}
} // namespace

SettingCheck judge(const SettingDef &def, const std::string &wanted, const SettingFacts &facts) {
    SettingCheck c{std::string(def.key), wanted, {}, Verdict::NotSent};
    const bool readable = isReadable(def);
    // A write-only setting's echo is from this apply; a readable one's report counts when it is
    // the read-back (always, unless the link went).
    if (facts.reported && (!readable || !facts.linkLost || facts.readBackRan)) {
        c.reported = *facts.reported;
        c.verdict = compared(def, wanted, *facts.reported);
        return c;
    }
    switch (facts.fate) {
    case CommandFate::NotSent: c.verdict = Verdict::NotSent; break;
    case CommandFate::Unconfirmed: c.verdict = Verdict::Unconfirmed; break;
    case CommandFate::Taken:
        c.verdict = !readable        ? Verdict::WrittenUnverified
                    : facts.linkLost ? Verdict::NotReadBack
                                     : Verdict::NotReported;
        break;
    }
    return c;
}

SettingCheck judgeReadBack(const SettingDef &def, SettingCheck c,
                           const std::optional<std::string> &reported, bool linkLost) {
    if (!isReadable(def)) return c;
    if (reported) {
        c.reported = *reported;
        if (sameValue(def, c.wanted, *reported))
            c.verdict = Verdict::Verified;
        else if (c.verdict != Verdict::NotSent)
            c.verdict = Verdict::NotTaken;
    } else if (!linkLost && c.verdict != Verdict::NotSent) {
        c.verdict = Verdict::NotReported;
    }
    return c;
}

} // namespace gnss::config
