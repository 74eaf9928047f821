#pragma once
// ConnectionController: turns a SourceSpec into a live link::Connection wired to the session:
// decoded sentences (from the link's one decoder) to the models, commands from the console
// through the command queue, baud detection for serial ports with "auto" (LinkOpener: the port it
// opened is handed over, open, at the rate found), connections made in the background,
// reconnects with growing waits and recording, each step reported in words. Nothing here blocks
// the thread it runs in.
#include "link/source_spec.h"

#include <QObject>
#include <memory>

namespace gnss {
class DialectRegistry;
namespace link {
class Connection;
class LinkOpener;
class VendorDetector;
class TransportFactory;
struct CommandResult;
} // namespace link
namespace ui {
class ReceiverSession;
}
} // namespace gnss

namespace gnss::app {

using link::SourceSpec;

class ConnectionController : public QObject {
    Q_OBJECT
public:
    enum class State { Disconnected, Detecting, Connecting, Connected, Reconnecting, Failed };
    Q_ENUM(State)

    ConnectionController(const DialectRegistry &registry, const link::TransportFactory &transports,
                         ui::ReceiverSession *session, QObject *parent = nullptr);
    ~ConnectionController() override;

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

signals:
    void stateChanged(gnss::app::ConnectionController::State state, const QString &text);
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

    const DialectRegistry &registry_;
    const link::TransportFactory &transports_;
    ui::ReceiverSession *session_;
    SourceSpec spec_;
    std::unique_ptr<link::LinkOpener> opener_;
    std::unique_ptr<link::Connection> connection_;
    // Asks who is on a link whose output names no vendor (declared after connection_: it goes
    // first, it listens to the connection's stream).
    std::unique_ptr<link::VendorDetector> identifier_;
    int detectedBaud_ = 0;
    QString detectionDetail_;
    State state_ = State::Disconnected;
    QString stateText_;
};

} // namespace gnss::app
