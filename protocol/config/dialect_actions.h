#pragma once
// What the settings engine needs from a dialect beyond its schema, as one small table keyed by
// dialect id: the sentences of the receiver-wide actions (save to flash, restore defaults,
// cold/warm/hot start), and which command changes the speed of the port the host is on.
//
// The dialect records carry no entries for these (the GeoStar schema lists its restarts as
// "action.*" rows; NVS and Nemerix only have typed encoders), so the data lives here: a new
// receiver family adds its rows to dialect_actions.cpp.
#include <span>
#include <string>
#include <string_view>

namespace gnss::config {

enum class Action { SaveToFlash, RestoreDefaults, ColdStart, WarmStart, HotStart };

struct ActionDef {
    std::string_view dialect; // "nvs"
    Action action;
    std::string_view body;   // sentence body without '$' and checksum: "PNVGCFG,W"
    std::string_view label;  // "Save to flash"
    std::string_view effect; // what it does, for the confirmation
};

// The actions a dialect offers, in the order of the Action enum.
std::span<const ActionDef> actionTable();
const ActionDef *findAction(std::string_view dialect, Action action);
// "$PNVGCFG,W*hh".
std::string actionSentence(const ActionDef &a);
std::string_view actionName(Action a); // "save", "defaults", "cold", "warm", "hot"

// The command that changes the speed of the port the host is connected to, by the start of its
// body ("PNVGRZA,1," — the NVS host is on COM1 by default), and the setting that holds the new
// speed ("port.COM1.baud"). The link follows that command to the new speed; other
// speed-changing commands (another port's) must not move it. Empty when the dialect has none.
struct LinkSpeed {
    std::string_view dialect, command, settingKey;
};
const LinkSpeed *linkSpeedCommand(std::string_view dialect);

} // namespace gnss::config
