#pragma once
// DialectReceiver: the simulated receiver of a family whose settings are its dialect's schema.
// It owns them (a SettingsStore seeded from the schema's defaults, with the copy in flash) and
// runs on two of them itself: the host port's speed (a power cycle brings it back from flash, a
// command that changes it switches the port) and the navigation rate (the epoch interval). The
// family's subclass holds the rest: what it sends, how it answers, what a reset clears.
#include "receiver.h"
#include "settings_store.h"

#include <string>

namespace gnss::sim {

// The schema keys of the settings the receiver runs on.
struct RunKeys {
    std::string baud; // the host port's speed, bit/s
    std::string rate; // navigation epochs a second; empty: one epoch a second
};

class DialectReceiver : public Receiver {
public:
    // The settings in force, by the schema's keys, with the copy in flash (settings().saved()).
    const SettingsStore &settings() const { return store_; }
    double epochInterval() const override;

protected:
    DialectReceiver(const Dialect &dialect, RunKeys keys, const SimOptions &options);

    // The port's speed in force (the current one while the store has none).
    int portSpeed() const;
    // A power cycle's settings: the copy in flash in force again, the port at its speed.
    void restoreFromFlash();

    SettingsStore store_;

private:
    RunKeys keys_;
};

} // namespace gnss::sim
