#pragma once
// LinkOpener: a source as the user named it, made into a link::Connection, the same way for the
// GUI and for every gnss-cli command.
//
// A serial port with baud "auto" (baud 0) is opened once and its speed found on it: the likely
// rates are tried (each reported, with what was seen there), and the port is handed to the
// connection open, at the rate found, so nothing reopens a device a lock could refuse. Every
// other source is made by the TransportFactory. The connection is returned unopened (open() it
// after connecting to its signals): it opens at once or in the background.
#include "link/baud_detector.h"
#include "link/connection.h"
#include "link/source_spec.h"
#include "link/transport_factory.h"

#include <QObject>

#include <memory>

namespace gnss::link {

class SentenceStream;

class LinkOpener : public QObject {
    Q_OBJECT
public:
    LinkOpener(const TransportFactory &factory, const DialectRegistry &registry,
               QObject *parent = nullptr);
    ~LinkOpener() override;

    // Starts; ready() or failed() follows, possibly before start() returns.
    void start(const SourceSpec &spec, DecoderOptions options = {});
    void cancel();
    bool isDetecting() const { return detector_ != nullptr; }

    // After ready(): the connection (ownership passes to the caller).
    std::unique_ptr<Connection> takeConnection() { return std::move(connection_); }
    // What baud detection tried (so far, while it runs), for the last start() on a serial port
    // with baud 0.
    const BaudDetection &detection() const { return detector_ ? detector_->result() : detection_; }
    // "38400 (valid NMEA)", "115200 (no data)", "9600 (data, no valid sentence)".
    static QString attemptText(const BaudAttempt &a);
    // The rates tried (the first `count`, all when -1), with what was seen there.
    static QString attemptsText(const BaudDetection &d, int count = -1);

    // The rates baud detection tries, in order (the user's preference); empty: the detector's
    // own order (kDetectionBauds, the port's current rate first).
    void setCandidateRates(QList<int> rates) { candidates_ = std::move(rates); }
    const QList<int> &candidateRates() const { return candidates_; }
    // Tuning for tests (defaults are those of BaudDetector).
    void setListenMs(int ms) { listenMs_ = ms; }

signals:
    void tryingRate(int baud);
    void ready();
    void failed(const QString &why);

private:
    void onDetection(const BaudDetection &result);
    void finishWith(std::unique_ptr<Transport> transport);

    const TransportFactory &factory_;
    const DialectRegistry &registry_;
    SourceSpec spec_;
    DecoderOptions options_;
    std::unique_ptr<Transport> port_; // the port being detected
    std::unique_ptr<SentenceStream> detectingStream_;
    std::unique_ptr<BaudDetector> detector_;
    std::unique_ptr<Connection> connection_;
    BaudDetection detection_;
    int listenMs_ = 0;
    QList<int> candidates_;
};

} // namespace gnss::link
