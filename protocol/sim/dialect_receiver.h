#pragma once
// DialectReceiver: the simulated receiver of a family whose settings are its dialect's schema.
// It owns them (a SettingsStore seeded from the schema's defaults, with the copy in flash) and
// runs on those the schema gives a role (SettingRole): the host port's speed (a power cycle
// brings it back from flash; a command that changes it switches the port), the output rate (the
// epoch interval) and the elevation and SNR masks (the satellites used). The family's subclass
// holds the rest: what it sends, how it answers, what a reset clears.
#include "sim/receiver.h"
#include "sim/settings_store.h"

#include <string_view>

namespace gnss::sim {

class DialectReceiver : public Receiver {
public:
    // The settings in force, by the schema's keys, with the copy in flash (settings().saved()).
    const SettingsStore &settings() const { return store_; }
    // 1 / the output rate in force (Hz); a second where the schema has no output rate.
    double epochInterval() const override;

protected:
    DialectReceiver(const Dialect &dialect, const SimOptions &options);

    // Every system, with the elevation and SNR masks in force (the defaults of UseMask where the
    // schema has no such setting).
    UseMask useMask() const override;
    // The port's speed in force (the current one while the store has none).
    int portSpeed() const;
    // A power cycle's settings: the copy in flash in force again, the port at its speed.
    void restoreFromFlash();

    SettingsStore store_;

private:
    // The key of the schema's setting of `role`; empty when it has none.
    std::string_view keyOf(SettingRole role) const;
};

} // namespace gnss::sim
