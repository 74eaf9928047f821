#pragma once
// ConnectionController: turns a SourceSpec into a live link::Connection wired to the session:
// bytes and decoded sentences to the models, commands from the console through the command
// queue, baud detection for serial ports with "auto", reconnects and recording reported.
#include "source_spec.h"

#include <QObject>
#include <memory>

namespace gnss {
class DialectRegistry;
namespace link {
class Connection;
class BaudDetector;
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
    enum class State { Disconnected, Detecting, Connected, Reconnecting, Failed };
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

    // Sends a complete sentence through the command queue; false (with why) before anything is
    // sent when there is no link or the sentence is refused.
    bool send(const QByteArray &sentence, QString *error = nullptr);

    bool startRecording(const QString &path);
    void stopRecording();
    bool recording() const;

signals:
    void stateChanged(gnss::app::ConnectionController::State state, const QString &text);
    void commandFinished(const QString &summary, bool ok);

private:
    void setState(State s, const QString &text);
    bool openWith(int baud);
    void onDetection(const link::BaudDetection &result);

    const DialectRegistry &registry_;
    ui::ReceiverSession *session_;
    SourceSpec spec_;
    std::unique_ptr<link::Connection> connection_;
    std::unique_ptr<link::BaudDetector> detector_;
    State state_ = State::Disconnected;
    QString stateText_;
};

} // namespace gnss::app
