#pragma once
// CorrectionSource: one stream of RTCM corrections for a receiver, whatever is behind it (an
// NTRIP caster, a base's TCP port, a radio modem, a recorded file). The application holds one,
// starts it, feeds dataReceived() to the receiver and to a CorrectionsMonitor, and shows
// statusText() and the errors.
//
// The base class holds what every source shares: the state, the status line, the wait before
// trying again (ntrip::ReconnectPolicy: 2 s doubling to 60 s) and the stall timeout (no bytes
// for 30 s: the connection is dropped and tried again). Subclasses open and close their
// connection and report what happens through the protected calls. Nothing blocks.
#include "ntrip/reconnect_policy.h"

#include <QAbstractSocket>
#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>

namespace gnss::corrections {

class CorrectionSource : public QObject {
    Q_OBJECT
public:
    enum class State {
        Idle,           // not started, stopped, or a file played to its end
        Connecting,     // connecting, or waiting for the caster's answer
        Receiving,      // connected: corrections flow (or are awaited)
        WaitingToRetry, // failed; the next attempt is planned (retryInMs())
        Failed,         // failed in a way trying again cannot mend (wrong password ...)
    };
    Q_ENUM(State)

    static constexpr int kDefaultStallMs = 30000;

    explicit CorrectionSource(QObject *parent = nullptr);
    ~CorrectionSource() override;

    // Starts (or restarts) the stream; failures arrive as signals, never as a blocked call.
    void start();
    // Stops: the connection is closed, no retry is planned, the state is Idle.
    void stop();

    State state() const { return state_; }
    bool isActive() const { return state_ == State::Connecting || state_ == State::Receiving; }
    // One line for a status bar: "Receiving RTCM from caster:2101/MOUNT (NTRIP 2) ...".
    QString statusText() const { return status_; }
    // The last error (empty before any).
    QString lastError() const { return error_; }
    // Whether the last failure was the request's own (a mountpoint the caster does not have),
    // not the source failing: a command line reports it as a wrong request (exit 2).
    bool failedOnRequest() const { return failedOnRequest_; }
    // What the source is, without credentials: "caster:2101/MOUNT", "/dev/ttyUSB1 at 38400 baud".
    virtual QString description() const = 0;

    quint64 bytesReceived() const { return bytes_; }
    // Milliseconds until the next attempt (0 when none is planned).
    int retryInMs() const { return retryTimer_.isActive() ? retryTimer_.remainingTime() : 0; }

    // The waits between attempts (tests use short ones).
    void setReconnectSettings(const ntrip::ReconnectSettings &settings);
    const ntrip::ReconnectPolicy &reconnectPolicy() const { return policy_; }
    // No bytes for this long while connecting or receiving: dropped and retried (0: never).
    void setStallTimeout(int ms);
    int stallTimeout() const { return stallMs_; }
    // Whether failures are retried at all (a command-line run may prefer to stop).
    void setAutoReconnect(bool on) { autoReconnect_ = on; }
    // The monotonic clock (ms) the reconnect policy's "a minute of data" is measured on.
    void setClock(std::function<qint64()> clock) { clock_ = std::move(clock); }

    // Words for a failed or broken TCP connection to `where` ("host:port").
    static QString describeSocketError(QAbstractSocket::SocketError error, const QString &where,
                                       const QString &host, const QString &qtText);

signals:
    // RTCM bytes as they arrive (de-chunked, without any HTTP framing).
    void dataReceived(const QByteArray &rtcm);
    void stateChanged(gnss::corrections::CorrectionSource::State state);
    void statusChanged(const QString &status);
    // A failure in words (the status line says what happens next).
    void errorOccurred(const QString &message);

protected:
    // Begins connecting; the subclass then reports with setConnecting/setReceiving/deliver/
    // failed. Called by start() and by each retry.
    virtual void openConnection() = 0;
    // Drops the connection at once, quietly (no reports from it afterwards).
    virtual void closeConnection() = 0;
    // What a stall means for this source, in words (the default speaks of a connection).
    virtual QString stallText(bool receiving) const;
    // Every status line and error passes here before it is kept or said: a source holding
    // credentials masks them (NtripSource), whatever the text came from (a caster's answer).
    virtual QString redacted(const QString &text) const { return text; }

    void setConnecting(const QString &status);
    void setReceiving(const QString &status);
    // Updates the status line without changing state.
    void setStatus(const QString &status);
    void deliver(const QByteArray &bytes);
    // A failure: tried again after the policy's wait when `retry` (and auto-reconnect is on),
    // else the source ends Failed. Ignored unless the source is connecting or receiving.
    void failed(const QString &message, bool retry);
    // A failure of the request itself (see failedOnRequest()), never retried.
    void refused(const QString &message);
    // Ended normally (a file played through): Idle, with `status`.
    void finished(const QString &status);
    qint64 nowMs() const { return clock_ ? clock_() : monotonic_.elapsed(); }

private:
    void setState(State s);
    void onStall();
    void onRetry();

    State state_ = State::Idle;
    QString status_;
    QString error_;
    bool failedOnRequest_ = false;
    ntrip::ReconnectPolicy policy_;
    QTimer retryTimer_;
    QTimer stallTimer_;
    int stallMs_ = kDefaultStallMs;
    bool autoReconnect_ = true;
    quint64 bytes_ = 0;
    QElapsedTimer monotonic_;
    std::function<qint64()> clock_;
};

} // namespace gnss::corrections
