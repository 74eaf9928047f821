#pragma once
// BaudDetector: finds the speed a receiver talks at. Tries the likely rates (the current one
// first, then the receivers' usual defaults), listens at each for checksum-valid sentences or
// CRC-valid RTCM 3 frames (a port that carries a base's corrections only), and settles on the
// first that gives them. When none does it says which rates it tried and what it
// saw, so the user knows whether to check the cable (nothing at all) or the framing/protocol
// (bytes, but never a valid sentence).
#include "core/stream_decoder.h"

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace gnss::link {

class SentenceStream;
class Transport;

struct BaudAttempt {
    int baud = 0;
    qint64 bytes = 0;
    int validSentences = 0;
    int badSentences = 0; // framed, but checksum wrong or missing
    int rtcmFrames = 0;   // RTCM 3 frames with a good CRC
};

struct BaudDetection {
    bool found = false;
    int baud = 0;
    std::vector<BaudAttempt> tried;
    QString error; // why nothing was found, in words
};

class BaudDetector : public QObject {
    Q_OBJECT
public:
    // Changes the speed of `stream`'s transport and counts the sentences `stream` (the link's
    // one decoder) finds at each speed.
    explicit BaudDetector(SentenceStream *stream, QObject *parent = nullptr);

    // Every rate from 4800 to 921600, `current` first, then the common receiver defaults.
    static QList<int> likelyRates(int current);

    void setCandidates(QList<int> rates) { candidates_ = std::move(rates); }
    // How long to listen at each rate (a 1 Hz receiver needs a bit over a second).
    void setListenMs(int ms) { listenMs_ = ms; }
    // Valid sentences (or RTCM frames) needed to settle on a rate.
    void setRequiredSentences(int n) { required_ = n; }
    // Sent at each rate, for receivers that only speak when asked (empty: listen only).
    void setProbe(const QByteArray &sentence) { probe_ = sentence; }

    void start();
    void cancel();
    bool isRunning() const { return running_; }
    const BaudDetection &result() const { return result_; }

signals:
    void tryingRate(int baud);
    void finished(const gnss::link::BaudDetection &result);

private:
    void tryNext();
    void onBytes(const QByteArray &bytes);
    void onEvent(const SentenceEvent &event);
    void onFrame();
    void rateDone();
    void done(bool found);

    QPointer<SentenceStream> stream_;
    QPointer<Transport> transport_;
    QList<int> candidates_;
    int index_ = -1;
    int listenMs_ = 1300;
    int settleMs_ = 120;
    int required_ = 2;
    QByteArray probe_;
    bool running_ = false;
    bool listening_ = false;
    BaudDetection result_;
    QTimer timer_;
    QMetaObject::Connection bytesConnection_, eventConnection_, frameConnection_;
};

} // namespace gnss::link
