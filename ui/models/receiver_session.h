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
    ReceiverSession(const DialectRegistry &registry, SessionModels models,
                    QObject *parent = nullptr);

    // Starts over (new connection): decoder, state and models are reset.
    void reset(const DecoderOptions &options = {});
    // Bytes received from the receiver, decoded by the session's own decoder (replays in tests,
    // or any source without a decoder of its own).
    void feed(const QByteArray &bytes);

    // With a link that decodes itself (link::Connection): its raw bytes (hex view, byte rate)
    // and each decoded sentence, and the decoder whose counters the statistics show.
    void noteBytes(const QByteArray &bytes);
    void consume(const SentenceEvent &ev, const Dialect *dialect);
    void setCounterSource(const StreamDecoder *decoder) { counterSource_ = decoder; }
    // A command sent to the receiver (shown in the console as sent).
    void noteSent(const QByteArray &sentence);
    // Flushes batched console lines and counters now (the timer does it every 100 ms).
    void refresh();

    const Dialect *dialect() const { return lastDialect_; }
    const LinkCounters &counters() const { return counters_; }
    const StreamDecoder *decoder() const { return decoder_.get(); }

signals:
    void dialectChanged(const gnss::Dialect *dialect);
    void countersChanged();

private:
    void onSentence(const SentenceEvent &ev, const Dialect *dialect);

    const DialectRegistry &registry_;
    SessionModels models_;
    std::unique_ptr<StreamDecoder> decoder_;
    const StreamDecoder *counterSource_ = nullptr;
    std::unique_ptr<StateTracker> tracker_;
    const Dialect *lastDialect_ = nullptr;
    QTimer refreshTimer_;
    LinkCounters counters_;
    quint64 bytesAtLastRate_ = 0, sentencesAtLastRate_ = 0;
    qint64 lastRateMs_ = 0;
};

} // namespace gnss::ui
