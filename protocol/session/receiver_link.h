#pragma once
// ReceiverLink: one receiver's link half, everything about it that is not a model or a window.
// It turns a SourceSpec into a live link::Connection (the one decoder, the command queue, the
// recorder), with baud detection for serial ports with "auto" (LinkOpener: the port it opened is
// handed over, open, at the rate found), vendor detection for a receiver whose output names no
// vendor, connections made in the background and reconnects with growing waits, each step
// reported in words. It owns the receiver's settings engine and the forwarder that writes
// corrections into its link. Whoever shows the receiver (ui::ReceiverSession) listens to
// connectionStarted() and to the connection's stream. Nothing here blocks the thread it runs in.
#include "link/source_spec.h"

#include <QObject>
#include <memory>

class QByteArray;

namespace gnss {
class DialectRegistry;
struct Dialect;
namespace config {
class SettingsEngine;
}
namespace corrections {
class CorrectionForwarder;
struct ForwarderStats;
} // namespace corrections
namespace link {
class Connection;
class LinkOpener;
class VendorDetector;
class TransportFactory;
struct CommandResult;
} // namespace link
} // namespace gnss

namespace gnss::session {

using link::SourceSpec;

class ReceiverLink : public QObject {
    Q_OBJECT
public:
    enum class State { Disconnected, Detecting, Connecting, Connected, Reconnecting, Failed };
    Q_ENUM(State)

    // A serial, TCP or gpsd link silent this long is opened again (Connection::setSilenceLimit).
    static constexpr int kSilenceLimitMs = 10000;

    ReceiverLink(const DialectRegistry &registry, const link::TransportFactory &transports,
                 QObject *parent = nullptr);
    ~ReceiverLink() override;

    bool connectTo(const SourceSpec &spec);
    void disconnectFromSource();
    SourceSpec source() const { return spec_; }
    State state() const { return state_; }
    QString stateText() const { return stateText_; }
    link::Connection *connection() const { return connection_.get(); }
    const link::TransportFactory &transports() const { return transports_; }
    // The rate baud detection found for this connection (0: none ran or none was found).
    int detectedBaud() const { return detectedBaud_; }
    // What baud detection tried and saw at each rate, in words (empty when none ran).
    QString detectionDetail() const { return detectionDetail_; }
    // Tries a lost link again now (a device was plugged in) instead of at the planned time.
    void retryNow();
    // The rates baud "auto" tries, in order (Preferences); empty: the built-in order.
    void setBaudCandidates(const QList<int> &rates);
    QList<int> baudCandidates() const;

    // Sends a complete sentence through the command queue; false (with why) before anything is
    // sent when there is no link, the link takes no commands, or the sentence is refused.
    bool send(const QByteArray &sentence, QString *error = nullptr);
    // Why the link takes no commands ("gpsd owns the port: ..."); empty when it does, or when
    // there is no link.
    QString sendRefusal() const;

    bool startRecording(const QString &path);
    void stopRecording();
    bool recording() const;

    // The receiver's settings (read, apply, verify): attached to this link's command queue by
    // whoever knows the dialect it speaks (attachSettings).
    config::SettingsEngine *settings() const { return settings_; }
    void attachSettings(const Dialect *dialect);

    // Corrections into this receiver: whole RTCM frames written between commands, none while
    // the link takes no writes (a replayed log, a receiver behind gpsd).
    void forwardCorrections(const QByteArray &bytes);
    // A new correction stream starts: a frame cut by the old one is not completed by the new.
    void resetCorrectionFraming();
    // Null while nothing is forwarded.
    const corrections::ForwarderStats *forwarderStats() const;

signals:
    void stateChanged(gnss::session::ReceiverLink::State state, const QString &text);
    // A new connection, not yet open: listeners wire themselves to its transport and stream
    // (and start over) before the first byte.
    void connectionStarted(gnss::link::Connection *connection);
    // The connection is gone (closed by the user or replaced).
    void connectionEnded();
    // A sentence sent through the command queue (for the console).
    void sentenceSent(const QByteArray &sentence);
    void commandFinished(const QString &summary, bool ok);
    // Baud detection: each rate tried, then the rate found (0: none).
    void detectingRate(int baud);
    void detectionFinished(int baud);

private:
    void identify(link::Connection *c);
    void setState(State s, const QString &text);
    void setConnected(const QString &description);
    void onOpenerReady();
    void onOpenerFailed(const QString &why);
    void wire(link::Connection *c);
    void updateForwarder();

    const DialectRegistry &registry_;
    const link::TransportFactory &transports_;
    config::SettingsEngine *settings_;
    SourceSpec spec_;
    std::unique_ptr<link::LinkOpener> opener_;
    std::unique_ptr<link::Connection> connection_;
    // Asks who is on a link whose output names no vendor (declared after connection_: it goes
    // first, it listens to the connection's stream).
    std::unique_ptr<link::VendorDetector> identifier_;
    std::unique_ptr<corrections::CorrectionForwarder> forwarder_;
    const link::Connection *forwardedTo_ = nullptr;
    int detectedBaud_ = 0;
    QString detectionDetail_;
    State state_ = State::Disconnected;
    QString stateText_;
};

} // namespace gnss::session
