#pragma once
// ModelFeed: decoded sentences in, models updated out (one per receiver session, or a test).
//
//   link's decoder → sentence events → console lines (batched)
//                                    → StateTracker → once per epoch: ReceiverStateModel,
//                                                     SatelliteModel
//   link's decoder counters → MessageStatsModel, byte/sentence/error counts (on a timer)
//
// The feed decodes nothing: it listens to the one decoder of the link (or of a test), and
// its counts are that decoder's. It knows no vendor; the dialect comes with each sentence.
#include "core/stream_decoder.h"
#include "models/console_model.h"
#include "models/message_stats_model.h"
#include "models/receiver_state_model.h"
#include "models/satellite_model.h"
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
    quint64 skippedBytes = 0; // bytes in neither a sentence nor an RTCM 3 frame: junk, binary
    quint64 rtcmFrames = 0;   // RTCM 3 frames in the stream (a base that interleaves them)
};

class ModelFeed : public QObject {
    Q_OBJECT
public:
    ModelFeed(const DialectRegistry &registry, SessionModels models, QObject *parent = nullptr);

    // Starts over (new connection): state and models are reset, the counts forgotten.
    void reset();

    // The link's raw bytes (hex view), each sentence its decoder decoded, and that decoder (its
    // counts are the session's: bytes, sentences, checksum and decode errors, per address).
    void noteBytes(const QByteArray &bytes);
    void consume(const SentenceEvent &ev, const Dialect *dialect);
    void setCounterSource(const StreamDecoder *decoder) { counterSource_ = decoder; }
    // A command sent to the receiver (shown in the console as sent).
    void noteSent(const QByteArray &sentence);
    // Flushes batched console lines and counters now (the timer does it every 100 ms).
    void refresh();

    const Dialect *dialect() const { return lastDialect_; }
    const LinkCounters &counters() const { return counters_; }

signals:
    void dialectChanged(const gnss::Dialect *dialect);
    void countersChanged();

private:
    void updateCounts();

    const DialectRegistry &registry_;
    SessionModels models_;
    const StreamDecoder *counterSource_ = nullptr;
    std::unique_ptr<StateTracker> tracker_;
    const Dialect *lastDialect_ = nullptr;
    QTimer refreshTimer_;
    LinkCounters counters_;
    quint64 bytesAtLastRate_ = 0, sentencesAtLastRate_ = 0;
    qint64 lastRateMs_ = 0;
};

} // namespace gnss::ui
