#pragma once
// StateTracker: decoded messages in, one ReceiverState snapshot per navigation epoch out.
// Standard messages go to the EpochAssembler (plus HDT heading and GST deviations); vendor
// messages go to the dialect's updateState hook.
#include "state/epoch_assembler.h"
#include "state/receiver_state.h"

namespace gnss {

class StateTracker {
public:
    using Callback = FunctionRef<void(const ReceiverState &)>;

    explicit StateTracker(const Dialect *dialect = nullptr) : epochs_(dialect), dialect_(dialect) {}
    void setDialect(const Dialect *d) {
        dialect_ = d;
        epochs_.setDialect(d);
    }
    void forgetSatellites() { epochs_.forgetSatellites(); }

    // One decoded message (with the dialect of the rule that decoded it, nullptr: standard).
    void add(const Sentence &s, const Message &m, const Dialect *ruleDialect,
             const Callback &onEpoch);
    void flush(const Callback &onEpoch);

    const ReceiverState &state() const { return state_; }
    // Whether both hold the same state and will turn the same messages into the same snapshots.
    bool sameFuture(const StateTracker &o) const {
        return dialect_ == o.dialect_ && state_ == o.state_ && epochs_.sameFuture(o.epochs_);
    }

private:
    EpochAssembler epochs_;
    const Dialect *dialect_;
    ReceiverState state_;
};

} // namespace gnss
