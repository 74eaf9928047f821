#pragma once
// ConnectionController: turns a SourceSpec into a live link::Connection wired to the session:
// bytes and decoded sentences to the models, commands from the console through the command
// queue, baud detection for serial ports with "auto" (the port it opened is handed over, open,
// at the rate found), connections made in the background, reconnects with growing waits and
// recording, each step reported in words. Nothing here blocks the thread it runs in.
#include "source_spec.h"

#include <QObject>
#include <memory>

namespace gnss {
class DialectRegistry;
namespace link {
class Connection;
class BaudDetector;
class Transport;
struct BaudAttempt;
struct BaudDetection;
struct CommandResult;
} // namespace link
namespace ui {
class ReceiverSession;
}
} // namespace gnss

namespace gnss::app {

class ConnectionController : public QObject {
    Q_OBJECT
public:
    enum class State { Disconnected, Detecting, Connecting, Connected, Reconnecting, Failed };
    Q_ENUM(State)

    ConnectionController(const DialectRegistry &registry, ui::ReceiverSession *session,
                         QObject *parent = nullptr);
    ~ConnectionController() override;

    bool connectTo(const SourceSpec &spec);
    void disconnectFromSource();
    SourceSpec source() const { return spec_; }
    State state() const { return state_; }
    QString stateText() const { return stateText_; }
    link::Connection *connection() const { return connection_.get(); }
    // The rate baud detection found for this connection (0: none ran or none was found).
    int detectedBaud() const { return detectedBaud_; }
    // What baud detection tried and saw at each rate, in words (empty when none ran).
    QString detectionDetail() const { return detectionDetail_; }
    // Tries a lost link again now (a device was plugged in) instead of at the planned time.
    void retryNow();

    // Sends a complete sentence through the command queue; false (with why) before anything is
    // sent when there is no link or the sentence is refused.
    bool send(const QByteArray &sentence, QString *error = nullptr);

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
    void setState(State s, const QString &text);
    void setConnected(const QString &description);
    bool detectBaud();
    std::unique_ptr<link::Transport> makeTransport(int baud);
    bool openWith(std::unique_ptr<link::Transport> transport);
    void onDetection(const link::BaudDetection &result);
    static QString attemptText(const link::BaudAttempt &a);

    const DialectRegistry &registry_;
    ui::ReceiverSession *session_;
    SourceSpec spec_;
    std::unique_ptr<link::Connection> connection_;
    std::unique_ptr<link::Transport> detecting_; // the port baud detection has open
    std::unique_ptr<link::BaudDetector> detector_;
    int detectedBaud_ = 0;
    QString detectionDetail_;
    State state_ = State::Disconnected;
    QString stateText_;
};

} // namespace gnss::app
