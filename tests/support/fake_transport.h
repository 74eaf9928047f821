#pragma once
// A transport for unit tests: what is written is kept (and can be answered by a script), what the
// test feeds is "received", and the link can be dropped on demand.
#include "builtin_registry.h"
#include "link/sentence_stream.h"
#include "link/transport.h"

#include <functional>

namespace gnss::link::test {

// The built-in dialects, for the decoders tests put on a fake link.
using gnss::test::builtinRegistry;

// (No Q_OBJECT: it adds no signals or slots, and so needs no moc.)
class FakeTransport : public Transport {
public:
    using Responder = std::function<void(FakeTransport &, const QByteArray &written)>;

    explicit FakeTransport(int baud = 0) : baud_(baud) {}

    bool open() override {
        if (refuseOpen) {
            fail(QStringLiteral("fake: cannot open"), false);
            return false;
        }
        ++opens;
        setState(State::Open);
        return true;
    }
    void close() override { setState(State::Closed); }
    QString description() const override { return QStringLiteral("fake link"); }
    int baud() const override { return baud_; }
    bool setBaud(int b) override {
        baud_ = b;
        bauds.append(b);
        return true;
    }
    void discardInput() override { ++discards; }
    qint64 pendingWriteBytes() const override { return pendingWrite; }

    // The receiver sends `bytes`.
    void feed(const QByteArray &bytes) { emit bytesReceived(bytes); }
    // The device disappears.
    void drop(const QString &why = QStringLiteral("fake: device gone")) { fail(why, true); }

    QList<QByteArray> written;
    QList<int> bauds;
    Responder responder;
    bool refuseOpen = false;
    int opens = 0;
    int discards = 0;
    qint64 pendingWrite = 0; // what the "port" still holds unsent

protected:
    bool writeBytes(const QByteArray &bytes) override {
        written.append(bytes);
        if (responder) responder(*this, bytes);
        return true;
    }

private:
    int baud_;
};

} // namespace gnss::link::test
