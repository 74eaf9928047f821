#pragma once
// CorrectionsController: the corrections path of the window. It owns the correction source the
// user started from the corrections dock (an NTRIP mountpoint or a base's TCP stream), feeds what
// arrives to the CorrectionsMonitor the dock shows and to the receiver session it serves (its
// ReceiverLink forwards whole frames into the receiver, never inside a command). The
// receiver's fix goes up to the caster as the GGA and to the monitor for the baseline. Caster,
// port, mountpoint, user and protocol are remembered in the injected QSettings; the password is
// used for this session only and never written anywhere.
#include "views/corrections_view.h"

#include "corrections/corrections_monitor.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>

class QSettings;

namespace gnss {
struct Epoch;
namespace session {
class ReceiverLink;
}
namespace corrections {
class CorrectionSource;
} // namespace corrections
namespace link {
class Connection;
}
} // namespace gnss

namespace gnss::app {

class PasswordKeychain;

class CorrectionsController : public QObject {
    Q_OBJECT
public:
    explicit CorrectionsController(QSettings *settings, QObject *parent = nullptr);
    ~CorrectionsController() override;

    // The last request started (without the password), for the dock's form.
    ui::CorrectionsRequest remembered() const;
    // Starts the source asked for (the one running is stopped first); false with `why` when the
    // request is incomplete: then nothing was started.
    bool start(const ui::CorrectionsRequest &request, QString *why = nullptr);
    void stop();
    bool active() const;
    QString statusText() const;
    // Asks the keychain for the remembered request's password, when the user kept one: the
    // answer comes as passwordRecalled().
    void recallPassword();
    static bool keychainAvailable();

    // The receiver the corrections go to (null: none). What it sends as RTCM 3 itself (a base's
    // port, a receiver that interleaves RTCM with its NMEA) is shown while no source runs: the
    // dock then says what the base sends.
    void setTarget(session::ReceiverLink *receiver);
    // Whether the monitor shows the receiver's own RTCM (no source started).
    bool showingOwnOutput() const { return ownOutput_; }
    // The receiver's latest fix: the GGA sent up, the baseline shown.
    void setRoverFix(const Epoch &epoch);

    const corrections::CorrectionsMonitor &monitor() const { return monitor_; }
    corrections::CorrectionSource *source() const { return source_.get(); }

signals:
    void statusChanged(const QString &text, bool active);
    // Bytes the source delivered (what goes to the receiver): for re-broadcasting them.
    void correctionsReceived(const QByteArray &bytes);
    void passwordRecalled(const QString &password);
    // What the keychain said, in words (it may be locked or absent).
    void keychainMessage(const QString &text);

private:
    void onData(const QByteArray &bytes);
    void onOwnFrame(const QByteArray &frame);
    void watch(link::Connection *connection);

    QSettings *settings_;
    corrections::CorrectionsMonitor monitor_;
    std::unique_ptr<corrections::CorrectionSource> source_;
    QPointer<session::ReceiverLink> target_;
    QTimer ageSampler_;
    PasswordKeychain *keychain_;
    bool ownOutput_ = false;
};

} // namespace gnss::app
