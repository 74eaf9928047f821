#pragma once
// NtripCaster: an NTRIP caster (revision 1 and 2) serving the streams its owner publishes.
//
//   request                                  answer
//   GET / (any revision)                     the source table, without a password:
//                                              NTRIP 1 "SOURCETABLE 200 OK", NTRIP 2 HTTP/1.1
//                                              with Content-Type: gnss/sourcetable
//   GET /UNKNOWN                             NTRIP 1: the source table; NTRIP 2: 404 Not Found
//                                              (before any credentials are looked at)
//   GET /MOUNT, wrong or no credentials      401 Unauthorized, WWW-Authenticate: Basic realm
//   GET /MOUNT, NTRIP 1                      "ICY 200 OK" CR LF CR LF, then the stream
//   GET /MOUNT, Ntrip-Version: Ntrip/2.0     HTTP/1.1 200 OK, gnss/data, chunked; the stream in
//                                              chunks, the last chunk when the caster closes
//   a malformed head                         400 Bad Request (405 for another method than GET)
//   no whole head within the head timeout    the connection is closed
//
// publish(mount, bytes) takes the source's bytes as they come: they are framed (RtcmFramer)
// and only whole RTCM 3 frames with a good CRC reach clients (what lies between frames, NMEA a
// receiver interleaves, does not). The frames also describe the mount in the source table
// (MountMonitor: message types and rates, systems, station position, bit rate). Every client
// has a bounded queue (StreamClients): one that does not read is dropped, nobody waits for it.
// Binds 127.0.0.1 unless told otherwise. Qt Core and Network; nothing blocks.
#include "ntrip/source_table.h"
#include "serve/stream_server.h"

#include <QElapsedTimer>

#include <map>
#include <memory>

namespace gnss::serve {

struct MountConfig {
    QString name;                // the mountpoint, without '/'
    bool needsPassword = true;   // a user of the caster's must authenticate (Basic)
    ntrip::StreamEntry describe; // identifier, network, country ...: the rest is filled in
};

// Requests refused, by kind, and clients dropped.
struct CasterCounters {
    quint64 badRequests = 0;  // 400
    quint64 notAllowed = 0;   // 405
    quint64 unauthorized = 0; // 401
    quint64 notFound = 0;     // unknown mountpoint (404, or the table for NTRIP 1)
    quint64 sourceTables = 0; // tables served
    quint64 streams = 0;      // streams started
    quint64 headTimeouts = 0;
    quint64 droppedSlow = 0;
    quint64 overCapacity = 0;
};

class NtripCaster : public StreamServer {
    Q_OBJECT
public:
    explicit NtripCaster(QObject *parent = nullptr);
    ~NtripCaster() override;

    // A mountpoint (the name checked by the owner: ntrip::checkMountpoint); again: replaced.
    void addMount(const MountConfig &mount);
    void addUser(const QString &user, const QString &password);
    void setRealm(const QString &realm) { realm_ = realm; }

    // Stops listening and closes every client (NTRIP 2 ones get the last chunk).
    void close();

    // Bytes of `mount`'s source; ignored for a mount the caster does not have.
    void publish(const QString &mount, const QByteArray &bytes);

    CasterCounters counters() const;
    // The source table as it is served now.
    QByteArray sourceTable() const;
    // The record of `mount` now (its configured fields and what was served).
    ntrip::StreamEntry describe(const QString &mount) const;
    // Bytes published to `mount` that were no part of a good frame.
    quint64 bytesNotRtcm(const QString &mount) const;

signals:
    // A client was given the stream of `client.mountpoint`.
    void streamStarted(const gnss::serve::ClientInfo &client);
    // A request refused: the status answered (400, 401, 404, 405; 200 for NTRIP 1's table
    // instead of an unknown mount) and why in words.
    void requestRefused(const gnss::serve::ClientInfo &client, int status, const QString &why);

protected:
    void accepted(QTcpSocket *socket) override;

private:
    struct Mount;
    struct Pending;
    void onReceived(quint64 id, const QByteArray &bytes);
    void answer(quint64 id, const Pending &p);
    void refuse(quint64 id, int status, bool v2, const QString &why, const QByteArray &extra = {});
    void serveTable(quint64 id, bool v2);
    bool authorised(const std::string &user, const std::string &password) const;

    std::map<QString, std::unique_ptr<Mount>> mounts_;
    std::map<quint64, std::unique_ptr<Pending>> pending_; // clients whose head is being read
    std::map<quint64, bool> v2_;                          // streaming clients: chunked or not
    std::map<QString, QString> users_;
    QString realm_ = QStringLiteral("NTRIP GNSS Workbench");
    CasterCounters counters_;
    QElapsedTimer clock_;
};

} // namespace gnss::serve
