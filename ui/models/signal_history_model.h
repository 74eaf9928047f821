#pragma once
// SignalHistoryModel: one receiver's signal history (gnss::SignalHistory: C/N0 of each satellite
// and signal over time, and the polar C/N0 map), for the Signal history and C/N0 map docks. Live,
// it follows the receiver's state model epoch by epoch and keeps the last minutes; for a log it is
// given the history of the whole log (or of the selected range) at once.
#include "state/signal_history.h"

#include <QObject>
#include <QTimer>

namespace gnss::ui {

class ReceiverStateModel;

class SignalHistoryModel : public QObject {
    Q_OBJECT
public:
    // Follows `state` (null: filled by setHistory only).
    explicit SignalHistoryModel(ReceiverStateModel *state, QObject *parent = nullptr);

    const SignalHistory &history() const { return history_; }
    // Live: how many minutes are kept (default 10).
    void setSpanMinutes(int minutes);
    int spanMinutes() const { return int(history_.span() / 60'000); }
    // Replaces what it holds (a log's history, computed elsewhere) and stops following the
    // state model (a log's cursor moving is not new epochs).
    void setHistory(SignalHistory history);
    void clear();

signals:
    // At most once a second while epochs come, and at once after setHistory or clear.
    void changed();

private:
    ReceiverStateModel *state_;
    bool following_ = true;
    SignalHistory history_;
    QTimer tick_;
    bool dirty_ = false;
};

} // namespace gnss::ui
