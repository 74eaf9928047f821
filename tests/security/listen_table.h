#pragma once
// Test helper: who listens on a TCP port of this machine, read from the kernel's socket tables
// (/proc/net/tcp and /proc/net/tcp6), as address texts ("127.0.0.1", "::1", "0.0.0.0", "::").
#include <QFile>
#include <QHostAddress>
#include <QList>
#include <QNetworkInterface>
#include <QString>
#include <QStringList>

namespace gnss::test {

namespace detail {

// A /proc/net/tcp address: 32-bit words in the host's (little-endian) order, as hex.
inline QHostAddress procAddress(const QByteArray &hex) {
    QByteArray bytes = QByteArray::fromHex(hex);
    for (qsizetype w = 0; w + 4 <= bytes.size(); w += 4)
        std::reverse(bytes.begin() + w, bytes.begin() + w + 4);
    if (bytes.size() == 4)
        return QHostAddress(quint32(quint8(bytes[0])) << 24 | quint32(quint8(bytes[1])) << 16 |
                            quint32(quint8(bytes[2])) << 8 | quint32(quint8(bytes[3])));
    if (bytes.size() == 16)
        return QHostAddress(reinterpret_cast<const quint8 *>(bytes.constData()));
    return {};
}

} // namespace detail

// The local addresses of the sockets in LISTEN state on `port` (empty: nobody listens).
inline QStringList listeningAddresses(quint16 port) {
    QStringList out;
    for (const char *table : {"/proc/net/tcp", "/proc/net/tcp6"}) {
        QFile f(QString::fromLatin1(table));
        if (!f.open(QIODevice::ReadOnly)) continue;
        f.readLine(); // the header
        while (!f.atEnd()) {
            const QList<QByteArray> fields = f.readLine().simplified().split(' ');
            if (fields.size() < 4 || fields[3] != "0A") continue; // 0A: TCP_LISTEN
            const QList<QByteArray> local = fields[1].split(':');
            bool ok = false;
            if (local.size() != 2 || local[1].toUInt(&ok, 16) != port || !ok) continue;
            out << detail::procAddress(local[0]).toString();
        }
    }
    return out;
}

// Whether every address listening on `port` is a loopback one (and someone listens).
inline bool listensOnLoopbackOnly(quint16 port, QString *seen = nullptr) {
    const QStringList addresses = listeningAddresses(port);
    if (seen) *seen = addresses.join(QStringLiteral(", "));
    if (addresses.isEmpty()) return false;
    for (const QString &a : addresses)
        if (!QHostAddress(a).isLoopback()) return false;
    return true;
}

// This machine's own addresses that are not loopback ones (IPv4), to connect to from here.
inline QList<QHostAddress> outwardAddresses() {
    QList<QHostAddress> out;
    for (const QHostAddress &a : QNetworkInterface::allAddresses())
        if (!a.isLoopback() && a.protocol() == QAbstractSocket::IPv4Protocol) out << a;
    return out;
}

} // namespace gnss::test
