#include "dialect_receiver.h"

#include <utility>

namespace gnss::sim {

DialectReceiver::DialectReceiver(const Dialect &dialect, RunKeys keys, const SimOptions &options)
    : Receiver(dialect, options), store_(dialect), keys_(std::move(keys)) {}

double DialectReceiver::epochInterval() const {
    const double hz = keys_.rate.empty() ? 1.0 : store_.real(keys_.rate, 1.0);
    return hz > 0 ? 1.0 / hz : Receiver::epochInterval();
}

int DialectReceiver::portSpeed() const {
    return static_cast<int>(store_.integer(keys_.baud, baud()));
}

void DialectReceiver::restoreFromFlash() {
    store_.restore();
    setBaudNow(portSpeed());
}

} // namespace gnss::sim
