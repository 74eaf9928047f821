#include "models/signal_history_model.h"

#include "models/receiver_state_model.h"

namespace gnss::ui {

namespace {
constexpr int kHistoryTickMs = 1000;
constexpr std::int64_t kDefaultSpanMs = 10 * 60'000;
} // namespace

SignalHistoryModel::SignalHistoryModel(ReceiverStateModel *state, QObject *parent)
    : QObject(parent), state_(state), history_(kDefaultSpanMs) {
    tick_.setInterval(kHistoryTickMs);
    connect(&tick_, &QTimer::timeout, this, [this] {
        if (!dirty_) return;
        dirty_ = false;
        emit changed();
    });
    if (!state_) return;
    connect(state_, &ReceiverStateModel::updated, this, [this] {
        if (!following_) return;
        if (state_->epochCount() == 0) { // a new connection starts over
            clear();
            return;
        }
        dirty_ = history_.add(state_->state().epoch) || dirty_;
    });
    tick_.start();
}

void SignalHistoryModel::setSpanMinutes(int minutes) {
    history_.setSpan(std::int64_t(qMax(1, minutes)) * 60'000);
    dirty_ = true;
}

void SignalHistoryModel::setHistory(SignalHistory history) {
    history_ = std::move(history);
    following_ = false;
    dirty_ = false;
    emit changed();
}

void SignalHistoryModel::clear() {
    const std::int64_t span = history_.span();
    history_.clear();
    history_.setSpan(span);
    dirty_ = false;
    emit changed();
}

} // namespace gnss::ui
