#include "sim/dialect_receiver.h"

namespace gnss::sim {

DialectReceiver::DialectReceiver(const Dialect &dialect, const SimOptions &options)
    : Receiver(dialect, options), store_(dialect) {}

std::string_view DialectReceiver::keyOf(SettingRole role) const {
    const SettingDef *def = findSettingByRole(dialect().settings, role);
    return def ? def->key : std::string_view();
}

double DialectReceiver::epochInterval() const {
    const std::string_view rate = keyOf(SettingRole::OutputRate);
    const double hz = rate.empty() ? 1.0 : store_.real(rate, 1.0);
    return hz > 0 ? 1.0 / hz : Receiver::epochInterval();
}

UseMask DialectReceiver::useMask() const {
    UseMask m;
    if (const auto key = keyOf(SettingRole::ElevationMask); !key.empty())
        m.elevationMask = store_.real(key, m.elevationMask);
    if (const auto key = keyOf(SettingRole::SnrMask); !key.empty())
        m.snrMask = store_.real(key, m.snrMask);
    return m;
}

int DialectReceiver::portSpeed() const {
    return static_cast<int>(store_.integer(keyOf(SettingRole::PortSpeed), baud()));
}

void DialectReceiver::restoreFromFlash() {
    store_.restore();
    setBaudNow(portSpeed());
}

} // namespace gnss::sim
