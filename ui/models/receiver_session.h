#pragma once
// ReceiverSession: bytes from a receiver in, models updated out.
//
//   bytes → StreamDecoder → console lines (batched)
//                         → StateTracker → once per epoch: ReceiverStateModel, SatelliteModel
//         decoder counters → MessageStatsModel (on a timer)
//
// The session knows no vendor; the dialect comes from the decoder (chosen or detected).
#include "console_model.h"
#include "core/stream_decoder.h"
#include "message_stats_model.h"
#include "receiver_state_model.h"
#include "satellite_model.h"
#include "state/state_tracker.h"

#include <QObject>
#include <QTimer>
#include <memory>

namespace gnss::ui {

struct SessionModels {
    ReceiverStateModel *state = nullptr;
    SatelliteModel *satellites = nullptr;
    MessageStatsModel *messages = nullptr;
    ConsoleModel *console = nullptr;
};

struct LinkCounters {
    double bytesPerSecond = 0;
    double sentencesPerSecond = 0;
    quint64 bytes = 0;
    quint64 sentences = 0;
    quint64 checksumErrors = 0;
    quint64 decodeErrors = 0;
};

class ReceiverSession : public QObject {
    Q_OBJECT
public:
    ReceiverSession(const DialectRegistry &registry, SessionModels models, QObject *parent = nullptr);

    // Starts over (new connection): decoder, state and models are reset.
    void reset(const DecoderOptions &options = {});
    // Bytes received from the receiver.
    void feed(const QByteArray &bytes);
    // A command sent to the receiver (shown in the console as sent).
    void noteSent(const QByteArray &sentence);
    // Flushes batched console lines and counters now (the timer does it every 100 ms).
    void refresh();

    const Dialect *dialect() const { return decoder_ ? decoder_->dialect() : nullptr; }
    const LinkCounters &counters() const { return counters_; }
    const StreamDecoder *decoder() const { return decoder_.get(); }

signals:
    void dialectChanged(const gnss::Dialect *dialect);
    void countersChanged();

private:
    void onSentence(const SentenceEvent &ev);

    const DialectRegistry &registry_;
    SessionModels models_;
    std::unique_ptr<StreamDecoder> decoder_;
    std::unique_ptr<StateTracker> tracker_;
    const Dialect *lastDialect_ = nullptr;
    QTimer refreshTimer_;
    LinkCounters counters_;
    quint64 bytesAtLastRate_ = 0, sentencesAtLastRate_ = 0;
    qint64 lastRateMs_ = 0;
};

} // namespace gnss::ui
