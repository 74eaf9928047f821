#pragma once
// The verdict rule of an apply, once: what became of each setting, from what is known when the
// apply ends (the outcome of its command, what the receiver read back or echoed, whether the
// link went in the middle), and again when the settings of an interrupted apply are read back.
// Pure functions of their arguments: tested without a queue (tests/config/tst_apply_verdicts).
// SettingsEngine gathers the facts and keeps its own memory (reported and written values).
#include "core/settings_schema.h"
#include "link/command_queue.h"

#include <QList>

#include <optional>
#include <string>
#include <vector>

namespace gnss::config {

enum class Verdict {
    Verified,          // read back with the value set
    Echoed,            // write-only: the command's answer carries the value set (PNVGRZA)
    NotTaken,          // read back (or echoed) with another value
    NotReported,       // readable, but the receiver did not report it after the change
    WrittenUnverified, // write-only: the command went through, nothing can read it back
    Refused,           // refused before anything was sent (a value its command cannot carry)
    NotSent,           // its command failed (refused, timed out, link lost, cancelled)
    NotReadBack,       // its command was taken, then the link went before the read-back
    Unconfirmed,       // its command went out, the link went before the answer: it may be set
};

// The verdicts of a setting that is as it was asked to be (or as far as can be known).
bool isGood(Verdict v);

struct SettingCheck {
    std::string key, wanted, reported;
    Verdict verdict = Verdict::NotReported;
};

// What became of the command (its sentences) that carries a setting.
enum class CommandFate {
    Taken,       // every sentence answered yes (or sent, for those without an answer)
    Unconfirmed, // one went out and its answer was lost, or only some went
    NotSent,     // none went out, or the receiver refused or did not answer
};

// A command accepted, or sent where no answer is expected.
bool succeeded(const link::CommandResult &r);
bool anyLinkLost(const QList<link::CommandResult> &commands);
// The fate of one command of settings (`sentences`) among an apply's `commands`.
CommandFate fateOf(const std::vector<std::string> &sentences,
                   const QList<link::CommandResult> &commands);

// What is known of one setting when its apply ends.
struct SettingFacts {
    // Readable: the value the receiver reported (the read-back, or before it when the link
    // went). Write-only: the value its echo in this apply said (PNVGRZA answers with the values
    // in force), a read-back too.
    std::optional<std::string> reported;
    CommandFate fate = CommandFate::Taken;
    bool linkLost = false;    // the link went during the apply
    bool readBackRan = false; // the read-back's queries went out before the link went
};

// The verdict of a setting set to `wanted`. Without the link lost, a reported value decides;
// with it, only a value read back does (what was reported before is the old value or an echo).
SettingCheck judge(const SettingDef &def, const std::string &wanted, const SettingFacts &facts);

// An interrupted apply's check once its settings are read back after the link returned
// (`reported`: nullopt when the receiver did not report it; `linkLost`: the read-back was cut
// short too). A setting whose command was not sent stays so unless it reads back as wanted.
SettingCheck judgeReadBack(const SettingDef &def, SettingCheck earlier,
                           const std::optional<std::string> &reported, bool linkLost);

} // namespace gnss::config
