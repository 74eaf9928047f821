#pragma once
// Transport: one source of receiver bytes and sink of commands, whatever is behind it (serial
// port, TCP socket, recorded log, built-in simulator). Everything above it (recorder, decoder,
// command queue, detectors) talks to this interface only, so tests inject a fake.
#include <QByteArray>
#include <QObject>
#include <QString>

namespace gnss::link {

// How long a network transport (TCP, gpsd) waits for its connection before it calls it failed.
constexpr int kDefaultConnectTimeoutMs = 5000;

class Transport : public QObject {
    Q_OBJECT
public:
    enum class State {
        Closed,     // not open (never opened, closed on purpose, or an opening that failed)
        Connecting, // opening in the background (a TCP connect, a log being indexed)
        Open,       // bytes flow
        Lost,       // was open and went away (unplugged, peer hung up, I/O error)
    };
    Q_ENUM(State)

    explicit Transport(QObject *parent = nullptr);
    ~Transport() override;

    // Opens the source, or starts opening it: true when it is Open, or Connecting (then it
    // becomes Open, or Closed with errorString() set and errorOccurred emitted, later). Returns
    // false with errorString() set (and errorOccurred emitted) when it fails at once. Never
    // blocks: a transport that needs time connects in the background.
    virtual bool open() = 0;
    virtual void close() = 0;
    // Queues bytes for the receiver; returns false when they cannot be sent (closed, read-only).
    // Bytes sent are also signalled (bytesSent), so a recorder sees every command.
    bool write(const QByteArray &bytes);
    // A short human-readable name: "/dev/ttyUSB0 at 115200 baud", "192.168.1.5:4001".
    virtual QString description() const = 0;

    // Line speed, for sources that have one (serial port, simulator); 0 = none.
    virtual int baud() const { return 0; }
    // Changes the line speed at once (the port stays open); false when the source has none.
    virtual bool setBaud(int baud);
    // Whether commands can be sent (a replayed log cannot, nor can a receiver behind gpsd).
    virtual bool canWrite() const { return true; }
    // Why commands cannot be sent, in words for the user, when canWrite() is false ("gpsd owns
    // the port ..."): the console and the settings dock show it instead of a bare refusal.
    virtual QString readOnlyReason() const { return {}; }
    // Bytes written but not yet on the line (the port's or socket's own buffer).
    virtual qint64 pendingWriteBytes() const { return 0; }
    // Drops whatever was received but not delivered yet (after a baud switch).
    virtual void discardInput() {}

    State state() const { return state_; }
    bool isOpen() const { return state_ == State::Open; }
    bool isConnecting() const { return state_ == State::Connecting; }
    // Gives up an open link that no longer works though its device says nothing (a hung
    // receiver, a half-open socket): it is Lost with `why`, as when it drops, then closed, so
    // that opening it again starts afresh.
    void abandon(const QString &why);
    QString errorString() const { return error_; }
    // Whether the last error is the request's own (a device or mountpoint the other end does not
    // have) rather than the source failing: retrying the same request cannot succeed, and a
    // command line reports it as a usage error.
    bool errorIsRequest() const { return errorIsRequest_; }

signals:
    void bytesReceived(const QByteArray &bytes);
    void bytesSent(const QByteArray &bytes);
    void stateChanged(gnss::link::Transport::State state);
    void errorOccurred(const QString &message);

protected:
    virtual bool writeBytes(const QByteArray &bytes) = 0;
    void setState(State s);
    // Records and signals an error; `lost` also moves an open transport to Lost. An opening in
    // the background that fails goes back to Closed.
    void fail(const QString &message, bool lost);
    // The same, for an error of the request itself (see errorIsRequest()).
    void failRequest(const QString &message);

private:
    void report(const QString &message, bool lost, bool request);

    State state_ = State::Closed;
    QString error_;
    bool errorIsRequest_ = false;
};

} // namespace gnss::link
