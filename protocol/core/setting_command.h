#pragma once
// SettingCommand: the command that writes a group of settings, and how they are read back.
//
// Each row of a dialect's settings schema names its command (SettingDef::command). The settings
// engine, `gnss-cli encode`, profiles and the simulator plan from these rows: which sentences
// write a change, in what order, which settings must go out together, and which queries read
// them back (settings_plan.h). Nothing plans from help or error text.
#include "core/settings_schema.h"

#include <span>
#include <string>
#include <string_view>

namespace gnss {

struct SettingCommand {
    // How plans and reports name it: "PNVGRZA,1", "PNMRX110", "ELEV".
    std::string_view name;
    // Its settings go out together (one sentence carries them all): a change of one is
    // completed with the others' values in force.
    bool together = false;
    // It changes the link the plan travels on (a port's speed or protocol, a restart): it goes
    // after every command that does not, and after their confirming reads.
    bool changesLink = false;
    // Place in a write plan among the commands of the same kind (changesLink), lowest first;
    // commands of one order go in the order their settings were given.
    int order = 0;
    // The receiver answers its writes with nothing: reading the settings back after the writes
    // is the confirmation, and the plan includes that read.
    bool confirmedByRead = false;
    // Checks one value of one of its settings; nullptr: validateSetting (type, range, options).
    Refusal (*validate)(const SettingDef &def, std::string_view value) = nullptr;
    // Sentences that write `values`: settings of this command only, each already valid alone,
    // in the order given. Refuses what spans its settings (one missing that it needs), building
    // nothing then.
    EncodeResult (*write)(std::span<const KeyValue> values) = nullptr;
    // Sentences that read `keys` (settings of this command) back; nullptr: the receiver cannot
    // report them (write-only settings).
    EncodeResult (*read)(std::span<const std::string> keys) = nullptr;
};

} // namespace gnss
