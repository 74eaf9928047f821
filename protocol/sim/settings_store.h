#pragma once
// SettingsStore: a simulated receiver's settings as its dialect's schema names them, a key→value
// map seeded from the schema's defaults, with the copy a save puts in flash.
//
// Commands are read with the dialect's decoders and applied through the dialect's own reading of
// them (Dialect::extractSettings): the simulator and the rest of the program cannot disagree on
// what a command sets. A value the schema does not take is not stored (the receiver keeps the
// one in force, as real receivers do). Replies that report settings are built with the rows'
// commands (SettingCommand::write), which echo the command's own form.
#include "core/dialect.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::sim {

class SettingsStore {
public:
    using Values = std::map<std::string, std::string, std::less<>>;

    // Every setting of the schema at its default (empty where the schema gives none); the
    // saved copy is the same.
    explicit SettingsStore(const Dialect &dialect);

    // The value in force ("" when the schema gives no default and nothing set it).
    const std::string &value(std::string_view key) const;
    long long integer(std::string_view key, long long fallback = 0) const;
    double real(std::string_view key, double fallback = 0) const;
    const Values &values() const { return current_; }

    // Sets one setting when the schema takes the value; false (nothing changed) otherwise.
    bool set(std::string_view key, std::string value);
    // A receiver's own starting value where the schema has no default (a base position that
    // depends on where the simulated receiver stands): in force and in flash.
    void seed(std::string_view key, std::string value);

    // Applies the settings a decoded command carries; the keys whose value changed.
    std::vector<std::string> apply(const Message &command);

    // The sentences that report `keys` as they stand, in the form of the command that writes
    // them (a reply that echoes the settings in force).
    EncodeResult report(std::span<const std::string> keys) const;

    // Flash: save what is in force, bring the saved copy back, or make the factory defaults the
    // saved copy.
    void save() { saved_ = current_; }
    void restore() { current_ = saved_; }
    void saveDefaults() { saved_ = defaults_; }
    const Values &saved() const { return saved_; }

private:
    const Dialect &dialect_;
    Values defaults_, current_, saved_;
};

} // namespace gnss::sim
