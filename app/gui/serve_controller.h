#pragma once
// ServeController: what the Serve dock asks, done with the window's receivers. One NTRIP caster
// (protocol/serve) with a mountpoint per stream the user ticks: a receiver's own RTCM (whole
// frames of its bytes: a base's port), or the corrections a receiver is fed through its
// Corrections dock (re-broadcast); and one raw TCP server passing a receiver's bytes on as they
// come. Both bind where the user says (127.0.0.1 by default); every client has a bounded queue,
// so one that does not read is dropped and never slows the receiver or the others.
#include "serve/ntrip_caster.h"
#include "serve/raw_stream_server.h"
#include "serve/serve_view.h"

#include <QPointer>
#include <QSet>
#include <QTimer>

#include <functional>
#include <memory>

namespace gnss::ui {
class ReceiverSession;
}

namespace gnss::app {

class CorrectionsController;

class ServeController : public QObject {
    Q_OBJECT
public:
    struct Receivers {
        std::function<QList<ui::ReceiverSession *>()> all;
        std::function<CorrectionsController *(ui::ReceiverSession *)> corrections;
    };
    explicit ServeController(Receivers receivers, QObject *parent = nullptr);

    // The dock's view (made again when the dock is): filled and followed.
    void attach(ui::ServeView *view);
    // The window's receivers changed: the streams offered follow.
    void refresh();

    // Starts the caster as `r` asks; false with `why` (nothing listens) when it cannot.
    bool startCaster(const ui::ServeCasterRequest &r, QString *why);
    void stopCaster();
    bool startRaw(const QString &address, int port, int receiver, QString *why);
    void stopRaw();
    // Disconnects a client of the named server ("NTRIP" or the raw port's name in the view's
    // client list); false when there is no such client (gone meanwhile).
    bool dropClient(const QString &server, quint64 id);

    // The servers while they run (null otherwise).
    const serve::NtripCaster *caster() const { return caster_.get(); }
    const serve::RawStreamServer *raw() const { return raw_.get(); }
    bool casterRunning() const { return caster_ != nullptr; }
    bool rawRunning() const { return raw_ != nullptr; }

signals:
    void message(const QString &text); // for the status bar

private:
    struct Stream {
        QPointer<ui::ReceiverSession> session;
        bool corrections = false; // the corrections it is fed, not its own bytes
        QString label, mount;
        bool suggested = false;
    };
    void tap(ui::ReceiverSession *s);
    void onBytes(ui::ReceiverSession *s, bool corrections, const QByteArray &bytes);
    void showState();
    void showClients();
    // The servers' names in the view's client list.
    static QString casterName() { return QStringLiteral("NTRIP"); }
    QString rawName() const { return tr("raw"); }

    Receivers receivers_;
    QPointer<ui::ServeView> view_;
    std::unique_ptr<serve::NtripCaster> caster_; // made anew at each start (users, mounts)
    std::unique_ptr<serve::RawStreamServer> raw_;
    QList<Stream> streams_;
    QList<Stream> served_; // the caster's mountpoints
    QPointer<ui::ReceiverSession> rawSession_;
    QSet<const ui::ReceiverSession *> tapped_;
    QTimer tick_;
};

} // namespace gnss::app
