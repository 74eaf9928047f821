// NtripCaster: requests read, answered and streamed; see ntrip_caster.h.
#include "serve/ntrip_caster.h"

#include "ntrip/caster_request.h"
#include "ntrip/ntrip_request.h"
#include "ntrip/source_table_writer.h"
#include "rtcm/rtcm_framer.h"
#include "serve/mount_monitor.h"

namespace gnss::serve {

namespace {

constexpr char kCasterServer[] = "Server: NTRIP GNSSWorkbench/0.1\r\n";

const char *casterReason(int status) {
    switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 401: return "Unauthorized";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    default: return "Error";
    }
}

// One HTTP chunk: size in hex, CR LF, the bytes, CR LF.
QByteArray httpChunk(const QByteArray &bytes) {
    return QByteArray::number(bytes.size(), 16) + "\r\n" + bytes + "\r\n";
}

// Equal without telling by how long it took where they differ.
bool sameSecret(const std::string &a, const std::string &b) {
    if (a.size() != b.size()) return false;
    unsigned char diff = 0;
    for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
    return diff == 0;
}

} // namespace

struct NtripCaster::Mount {
    MountConfig config;
    rtcm::RtcmFramer framer;
    MountMonitor monitor;
};

struct NtripCaster::Pending {
    ntrip::CasterRequestParser parser;
};

NtripCaster::NtripCaster(QObject *parent) : StreamServer(parent) {
    clock_.start();
    connect(&clients_, &StreamClients::received, this, &NtripCaster::onReceived);
    connect(&clients_, &StreamClients::disconnected, this, [this](const ClientInfo &c) {
        pending_.erase(c.id);
        v2_.erase(c.id);
    });
}

NtripCaster::~NtripCaster() = default;

void NtripCaster::accepted(QTcpSocket *socket) {
    const quint64 id = clients_.add(socket, true);
    if (id) pending_[id] = std::make_unique<Pending>();
}

void NtripCaster::addMount(const MountConfig &mount) {
    auto m = std::make_unique<Mount>();
    m->config = mount;
    mounts_[mount.name] = std::move(m);
}

void NtripCaster::addUser(const QString &user, const QString &password) {
    users_[user] = password;
}

void NtripCaster::close() {
    stopListening();
    clients_.closeAll([this](const ClientInfo &c) {
        const auto it = v2_.find(c.id);
        return it != v2_.end() && it->second ? QByteArray("0\r\n\r\n") : QByteArray();
    });
}

CasterCounters NtripCaster::counters() const {
    CasterCounters c = counters_;
    c.headTimeouts = clients_.headTimeouts();
    c.droppedSlow = clients_.droppedSlow();
    c.overCapacity = clients_.overCapacity();
    return c;
}

ntrip::StreamEntry NtripCaster::describe(const QString &mount) const {
    const auto it = mounts_.find(mount);
    if (it == mounts_.end()) return {};
    const Mount &m = *it->second;
    ntrip::StreamEntry e = m.config.describe;
    e.mountpoint = m.config.name.toStdString();
    if (e.identifier.empty()) e.identifier = e.mountpoint;
    if (e.generator.empty()) e.generator = "GNSS Workbench";
    if (e.compression.empty()) e.compression = "none";
    if (e.country.empty()) e.country = "XXX";
    if (e.network.empty()) e.network = "LOCAL";
    if (!e.solution) e.solution = 0;
    e.authentication = m.config.needsPassword ? "B" : "N";
    m.monitor.describe(e, clock_.elapsed());
    return e;
}

quint64 NtripCaster::bytesNotRtcm(const QString &mount) const {
    const auto it = mounts_.find(mount);
    return it == mounts_.end() ? 0 : it->second->framer.stats().bytesSkipped;
}

QByteArray NtripCaster::sourceTable() const {
    std::vector<ntrip::StreamEntry> streams;
    for (const auto &[name, m] : mounts_) streams.push_back(describe(name));
    return QByteArray::fromStdString(ntrip::writeSourceTable(streams));
}

void NtripCaster::publish(const QString &mount, const QByteArray &bytes) {
    const auto it = mounts_.find(mount);
    if (it == mounts_.end()) return;
    Mount &m = *it->second;
    QByteArray frames;
    const std::int64_t now = clock_.elapsed();
    m.framer.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())),
                  [&](const rtcm::RtcmFrame &f) {
                      frames.append(reinterpret_cast<const char *>(f.bytes.data()),
                                    qsizetype(f.bytes.size()));
                      m.monitor.frame(f, now);
                  });
    if (frames.isEmpty()) return;
    QByteArray chunk; // made once, for the first NTRIP 2 client
    for (quint64 id : clients_.streamingIds()) {
        const ClientInfo *c = clients_.find(id);
        if (!c || c->mountpoint != mount) continue;
        if (v2_[id]) {
            if (chunk.isEmpty()) chunk = httpChunk(frames);
            clients_.send(id, chunk);
        } else {
            clients_.send(id, frames);
        }
    }
}

void NtripCaster::onReceived(quint64 id, const QByteArray &bytes) {
    const auto it = pending_.find(id);
    if (it == pending_.end()) return; // a streaming client's GGA: read and ignored
    Pending &p = *it->second;
    const auto state =
            p.parser.feed(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    if (state == ntrip::CasterRequestParser::State::NeedMore) return;
    const std::unique_ptr<Pending> done = std::move(it->second);
    pending_.erase(it);
    if (state == ntrip::CasterRequestParser::State::Malformed) {
        const int status = done->parser.statusCode();
        (status == 405 ? counters_.notAllowed : counters_.badRequests)++;
        const bool v2 = done->parser.request().version == ntrip::NtripVersion::V2;
        refuse(id, status, v2,
               tr("malformed request: %1").arg(QString::fromStdString(done->parser.reason())),
               status == 405 ? QByteArray("Allow: GET\r\n") : QByteArray());
        return;
    }
    answer(id, *done);
}

void NtripCaster::answer(quint64 id, const Pending &p) {
    const ntrip::CasterRequest &r = p.parser.request();
    const bool v2 = r.version == ntrip::NtripVersion::V2;
    if (r.wantsSourceTable()) return serveTable(id, v2);
    const QString name = QString::fromStdString(r.mountpoint);
    const auto it = mounts_.find(name);
    if (it == mounts_.end()) {
        // Before the credentials: an unknown mountpoint says nothing about users.
        ++counters_.notFound;
        const QString why = tr("no mountpoint %1").arg(name);
        if (const ClientInfo *c = clients_.find(id)) emit requestRefused(*c, v2 ? 404 : 200, why);
        if (v2) return refuse(id, 404, true, why);
        return serveTable(id, false);
    }
    const Mount &m = *it->second;
    if (m.config.needsPassword && !authorised(r.user, r.password)) {
        ++counters_.unauthorized;
        const QString why = r.hasAuthorization ? tr("wrong user name or password for %1").arg(name)
                                               : tr("no credentials for %1").arg(name);
        QString realm = realm_;
        realm.remove(QLatin1Char('"'));
        return refuse(id, 401, v2, why,
                      "WWW-Authenticate: Basic realm=\"" + realm.toLatin1() + "\"\r\n");
    }
    ++counters_.streams;
    QByteArray head;
    if (v2)
        head = QByteArray("HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\n") + kCasterServer +
               "Content-Type: gnss/data\r\nTransfer-Encoding: chunked\r\n"
               "Cache-Control: no-store\r\nConnection: close\r\n\r\n";
    else
        head = "ICY 200 OK\r\n\r\n";
    v2_[id] = v2;
    clients_.send(id, head);
    clients_.start(id, m.config.needsPassword ? QString::fromStdString(r.user) : QString(), name);
    if (const ClientInfo *c = clients_.find(id)) emit streamStarted(*c);
}

void NtripCaster::serveTable(quint64 id, bool v2) {
    ++counters_.sourceTables;
    const QByteArray table = sourceTable();
    QByteArray head = v2 ? QByteArray("HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\n") +
                                      kCasterServer + "Content-Type: gnss/sourcetable\r\n"
                         : QByteArray("SOURCETABLE 200 OK\r\n") + kCasterServer +
                                      "Content-Type: text/plain\r\n";
    head += "Content-Length: " + QByteArray::number(table.size()) + "\r\nConnection: close\r\n\r\n";
    clients_.refuse(id, head + table, tr("source table sent"));
}

void NtripCaster::refuse(quint64 id, int status, bool v2, const QString &why,
                         const QByteArray &extra) {
    const QByteArray body = QByteArray::number(status) + " " + casterReason(status) + "\r\n";
    QByteArray reply = (v2 ? "HTTP/1.1 " : "HTTP/1.0 ") + QByteArray::number(status) + " " +
                       casterReason(status) + "\r\n";
    if (v2) reply += "Ntrip-Version: Ntrip/2.0\r\n";
    reply += kCasterServer + extra +
             "Content-Type: text/plain\r\nContent-Length: " + QByteArray::number(body.size()) +
             "\r\nConnection: close\r\n\r\n" + body;
    if (status != 404)
        if (const ClientInfo *c = clients_.find(id)) emit requestRefused(*c, status, why);
    clients_.refuse(id, reply, why);
}

bool NtripCaster::authorised(const std::string &user, const std::string &password) const {
    const auto it = users_.find(QString::fromStdString(user));
    if (user.empty() || it == users_.end()) return false;
    return sameSecret(password, it->second.toStdString());
}

} // namespace gnss::serve
