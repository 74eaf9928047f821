#pragma once
// ReceiverStateModel: the latest receiver state, published once per navigation epoch.
// Panels (fix, RTK, attitude, charts, deviation) read state() when updated() fires; they never
// see a sentence. Fed by a ModelFeed (or directly by tests).
#include "state/receiver_state.h"

#include <QDateTime>
#include <QObject>

namespace gnss::ui {

class ReceiverStateModel : public QObject {
    Q_OBJECT
public:
    explicit ReceiverStateModel(QObject *parent = nullptr) : QObject(parent) {}

    const ReceiverState &state() const { return state_; }
    // Host time of the latest epoch (invalid before the first).
    QDateTime lastEpochTime() const { return lastEpoch_; }
    quint64 epochCount() const { return epochs_; }

    // Publishes a new epoch's state (copied) and emits updated().
    void publish(const ReceiverState &s,
                 const QDateTime &hostTime = QDateTime::currentDateTimeUtc()) {
        state_ = s;
        lastEpoch_ = hostTime;
        ++epochs_;
        emit updated();
    }
    // Forget everything (new connection).
    void clear() {
        state_ = ReceiverState{};
        lastEpoch_ = {};
        epochs_ = 0;
        emit updated();
    }

signals:
    void updated();

private:
    ReceiverState state_;
    QDateTime lastEpoch_;
    quint64 epochs_ = 0;
};

} // namespace gnss::ui
