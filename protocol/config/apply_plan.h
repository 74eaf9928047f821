#pragma once
// The plan of an apply, from the dialect record alone: which settings go together (the rows of
// one command, completed with the values in force), in which order the commands go (restarts,
// then speed changes, the host's own port last of them, then protocol changes), and which speed
// the host's side of the line follows to after a speed command. Pure functions: tested without a
// queue (tests/config/tst_apply_plan). SettingsEngine sends what they plan.
#include "core/dialect.h"
#include "core/settings_schema.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::config {

// The value in force of a setting (nullopt: not known).
using ValueInForce = std::function<std::optional<std::string>(std::string_view key)>;

// `changes` and the other settings of the commands they use that write several together
// (PNVGRZA,1: baud and protocol), each with its value in force or else its default; the ones
// added also go to `companions` when given.
std::vector<KeyValue> withCompanions(const Dialect &d, std::vector<KeyValue> changes,
                                     const ValueInForce &inForce,
                                     std::vector<KeyValue> *companions = nullptr);

// 0 for a command that changes nothing the rest depends on, 1 a restart, 2 another port's speed,
// 3 the host's port's speed, 4 a change of protocol (after it nothing else would be answered).
int effectRank(const Dialect &d, const std::string &sentence);
// Sorts `sentences` by effectRank, keeping the order of equals.
void orderForSending(const Dialect &d, std::vector<std::string> &sentences);

// For a speed command: the rate the host's side of the line is at after it (another port's
// speed: `lineBaud`, unchanged; the host's port: the speed set among `applying`). Nullopt for
// any other command, or when the line's rate is not known (`lineBaud` <= 0).
std::optional<int> lineBaudAfter(const Dialect &d, const std::string &sentence, int lineBaud,
                                 const std::vector<KeyValue> &applying);

} // namespace gnss::config
