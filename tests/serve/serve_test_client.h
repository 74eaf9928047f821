#pragma once
// A test's client of the servers in protocol/serve: a QTcpSocket on 127.0.0.1 that sends a
// request (or nothing) and keeps every byte it receives, and the RTCM the tests publish (the
// simulated base station's frames, with NMEA between them that a caster must not pass on).
#include "ntrip/chunked_decoder.h"
#include "rtcm_fixtures.h"

#include <QTcpSocket>
#include <QTest>

namespace serve_test {

struct TestClient {
    QTcpSocket socket;
    QByteArray received;
    bool closed = false;
    bool reading = true; // false: never reads (a slow client)

    explicit TestClient(quint16 port, const QByteArray &request = {}, bool read = true)
        : reading(read) {
        QObject::connect(&socket, &QTcpSocket::readyRead, [this] {
            if (reading) received += socket.readAll();
        });
        QObject::connect(&socket, &QTcpSocket::disconnected, [this] { closed = true; });
        if (!reading) socket.setReadBufferSize(1024);
        socket.connectToHost(QStringLiteral("127.0.0.1"), port);
        if (socket.waitForConnected(3000) && !request.isEmpty()) socket.write(request);
    }
    // The body after the reply head (up to CR LF CR LF).
    QByteArray body() const {
        const int end = int(received.indexOf("\r\n\r\n"));
        return end < 0 ? QByteArray() : received.mid(end + 4);
    }
    QByteArray statusLine() const { return received.left(received.indexOf("\r\n")); }
};

// The NTRIP 2 body without its chunking; empty with `error` set when it is malformed.
inline QByteArray unchunked(const QByteArray &body, bool *finished = nullptr) {
    gnss::ntrip::ChunkedDecoder d;
    std::string out;
    d.feed(std::string_view(body.constData(), std::size_t(body.size())), out);
    if (finished) *finished = d.status() == gnss::ntrip::ChunkedDecoder::Status::Finished;
    return d.status() == gnss::ntrip::ChunkedDecoder::Status::Error
                   ? QByteArray()
                   : QByteArray::fromStdString(out);
}

inline QByteArray v1Request(const QByteArray &mount, const QByteArray &userPass = {}) {
    QByteArray r = "GET /" + mount + " HTTP/1.0\r\nUser-Agent: NTRIP test\r\n";
    if (!userPass.isEmpty()) r += "Authorization: Basic " + userPass.toBase64() + "\r\n";
    return r + "\r\n";
}

inline QByteArray v2Request(const QByteArray &mount, const QByteArray &userPass = {}) {
    QByteArray r = "GET /" + mount +
                   " HTTP/1.1\r\nHost: 127.0.0.1\r\nNtrip-Version: Ntrip/2.0\r\n"
                   "User-Agent: NTRIP test\r\n";
    if (!userPass.isEmpty()) r += "Authorization: Basic " + userPass.toBase64() + "\r\n";
    return r + "Connection: close\r\n\r\n";
}

} // namespace serve_test
