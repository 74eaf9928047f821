#pragma once
// A small NTRIP caster for tests, on 127.0.0.1 (QTcpServer, in the test's event loop).
//
// It answers like a real caster: an NTRIP 2 request (HTTP/1.1 + Ntrip-Version) gets an HTTP
// reply with chunked gnss/data, anything else "ICY 200 OK" (or, with v1Only, everyone gets
// NTRIP 1 answers); wrong credentials get 401, an unknown mountpoint the source table, GET /
// the source table. What the test pushes with send() goes to every streaming client, cut into
// HTTP chunks of the configured sizes for NTRIP 2 clients. Every request and every byte a
// client sends after its request (the GGA upload) is kept for the test to look at.
#include "local_port.h"
#include "ntrip/base64.h"
#include "ntrip/gga_upload.h"

#include <QTcpServer>
#include <QTcpSocket>

#include <memory>
#include <vector>

namespace corrections_test {

// The rover position the GGA upload tests give the source (Moscow, near the MOUNT stream).
inline gnss::ntrip::GgaPosition roverPosition() {
    gnss::ntrip::GgaPosition p;
    p.latDeg = 55.7512;
    p.lonDeg = 37.6184;
    p.altitudeMsl = 152;
    return p;
}

// No Q_OBJECT: it has no signals of its own (lambdas do the connecting), so no moc run.
class TstCaster : public QObject {
public:
    QByteArray user = "rover7"; // empty: no authentication asked
    QByteArray password = "s3cret-pw";
    QByteArray mountpoint = "MOUNT";
    bool wantsGga = true; // the STR's nmea flag
    bool v1Only = false;  // answer NTRIP 1 whatever the request
    bool silent = false;  // answer the request, then never send data (stall)
    std::vector<int> chunkSizes = {7, 13, 1, 64};
    QByteArray rawReply; // when set: sent instead of any answer, then the connection closes

    QList<QByteArray> requests; // request heads as received
    QByteArray uploads;         // bytes clients sent after their request (GGA)
    int connections = 0;

    bool listen(quint16 port = 0) {
        if (!server_.listen(QHostAddress::LocalHost, port)) return false;
        port_ = server_.serverPort();
        return true;
    }
    void close() { server_.close(); }
    quint16 port() const { return port_; }
    int streamingClients() const {
        int n = 0;
        for (const auto &c : clients_) n += c->streaming ? 1 : 0;
        return n;
    }

    QByteArray sourceTable() const {
        return "STR;" + mountpoint +
               ";Test base;RTCM 3.2;1005(1),1074(1),1084(1);1;GPS+GLO;TEST;"
               "RUS;55.75;37.62;" +
               QByteArray(wantsGga ? "1" : "0") +
               ";0;gnss-sim;none;B;N;9600;\r\n"
               "STR;FAR;Far base;RTCM 3.3;1005(10);2;GPS;TEST;RUS;59.93;30.34;0;0;x;none;B;N;"
               "9600;\r\n"
               "STR;OLD;Old base;RTCM 2.3;1;2;GPS;TEST;RUS;55.76;37.63;0;0;x;none;B;N;2400;\r\n"
               "CAS;127.0.0.1;2101;Test;Tests;0;RUS;55.75;37.62;;0;\r\n"
               "NET;TEST;Tests;B;N;none;none;none;\r\n"
               "ENDSOURCETABLE\r\n";
    }

    // Sends `bytes` to every streaming client (chunked for NTRIP 2 clients).
    void send(const QByteArray &bytes) {
        for (const auto &c : clients_) {
            if (!c->streaming) continue;
            if (!c->v2) {
                c->socket->write(bytes);
                continue;
            }
            QByteArray out;
            for (int pos = 0; pos < bytes.size();) {
                const int n = std::min<int>(chunkSizes[c->nextChunk++ % chunkSizes.size()],
                                            int(bytes.size()) - pos);
                out += QByteArray::number(n, 16) + "\r\n" + bytes.mid(pos, n) + "\r\n";
                pos += n;
            }
            c->socket->write(out);
        }
    }
    // Raw bytes to every streaming client, whatever its revision (malformed chunks).
    void sendRaw(const QByteArray &bytes) {
        for (const auto &c : clients_)
            if (c->streaming) c->socket->write(bytes);
    }
    // Closes every client connection (the caster "drops" them).
    void dropClients() {
        const auto dropped = std::move(clients_);
        clients_.clear();
        for (const auto &c : dropped) c->socket->abort();
    }

    TstCaster() {
        connect(&server_, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *s = server_.nextPendingConnection()) {
                ++connections;
                auto c = std::make_shared<Client>();
                c->socket = s;
                s->setParent(this);
                clients_.push_back(c);
                connect(s, &QTcpSocket::readyRead, this, [this, c] { onRead(*c); });
                connect(s, &QTcpSocket::disconnected, this, [this, c] {
                    std::erase(clients_, c);
                    c->socket->deleteLater();
                });
            }
        });
    }

private:
    struct Client {
        QTcpSocket *socket = nullptr;
        QByteArray head;
        bool headDone = false;
        bool streaming = false;
        bool v2 = false;
        std::size_t nextChunk = 0;
    };

    void onRead(Client &c) {
        const QByteArray bytes = c.socket->readAll();
        if (c.headDone) {
            uploads += bytes;
            return;
        }
        c.head += bytes;
        const int end = c.head.indexOf("\r\n\r\n");
        if (end < 0) return;
        const QByteArray rest = c.head.mid(end + 4);
        c.head.truncate(end + 4);
        c.headDone = true;
        requests.append(c.head);
        uploads += rest;
        answer(c);
    }

    void answer(Client &c) {
        if (!rawReply.isEmpty()) {
            c.socket->write(rawReply);
            c.socket->disconnectFromHost();
            return;
        }
        const QList<QByteArray> lines = c.head.split('\n');
        const QList<QByteArray> first = lines.value(0).trimmed().split(' ');
        const QByteArray path = first.value(1);
        c.v2 = !v1Only && first.value(2) == "HTTP/1.1" && c.head.contains("Ntrip-Version: Ntrip/2");
        QByteArray auth;
        for (const QByteArray &l : lines)
            if (l.startsWith("Authorization: Basic ")) auth = l.mid(21).trimmed();
        const auto decoded = gnss::ntrip::base64Decode(auth.toStdString());
        const bool authorised = user.isEmpty() || // an open caster
                                (decoded && *decoded == (user + ":" + password).toStdString());

        if (path == "/" || path.mid(1) != mountpoint) {
            const QByteArray table = sourceTable();
            c.socket->write(c.v2 ? "HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\nContent-Type: "
                                   "gnss/sourcetable\r\nContent-Length: " +
                                            QByteArray::number(table.size()) + "\r\n\r\n" + table
                                 : "SOURCETABLE 200 OK\r\nContent-Type: text/plain\r\n"
                                   "Content-Length: " +
                                            QByteArray::number(table.size()) + "\r\n\r\n" + table);
            c.socket->disconnectFromHost();
            return;
        }
        if (!authorised) {
            c.socket->write(c.v2 ? "HTTP/1.1 401 Unauthorized\r\nNtrip-Version: Ntrip/2.0\r\n"
                                   "WWW-Authenticate: Basic realm=\"/" +
                                            mountpoint + "\"\r\nContent-Length: 0\r\n\r\n"
                                 : QByteArray("HTTP/1.0 401 Unauthorized\r\n"));
            c.socket->disconnectFromHost();
            return;
        }
        c.socket->write(c.v2 ? "HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\nContent-Type: "
                               "gnss/data\r\nTransfer-Encoding: chunked\r\nCache-Control: "
                               "no-store\r\n\r\n"
                             : "ICY 200 OK\r\n");
        c.streaming = !silent;
    }

    QTcpServer server_;
    quint16 port_ = 0;
    std::vector<std::shared_ptr<Client>> clients_;
};

using gnss::test::closedPort;

} // namespace corrections_test
