#pragma once
// For the end-to-end suites that record a link: a Connection on a transport (the built-in
// dialects) recording to a file, with every byte its transport delivered kept to hold the
// recording against. (tst_link_pty's hang-up and recording tests build the same by hand.)
#include "builtin_registry.h"
#include "link/connection.h"
#include "link/recording.h"
#include "link/transport.h"

#include <memory>

namespace gnss::link::test {

struct RecordedLink {
    RecordedLink(std::unique_ptr<Transport> transport, const QString &logPath)
        : conn(std::move(transport), gnss::test::builtinRegistry()), log(logPath) {
        recording = conn.startRecording(log);
        QObject::connect(conn.transport(), &Transport::bytesReceived, &conn,
                         [this](const QByteArray &b) { received += b; });
    }
    // Closes the link and the recording and reads it back (false with `error` set).
    bool finish(Recording &r, QString &error) {
        conn.close();
        conn.stopRecording();
        return loadRecording(log, r, error);
    }

    Connection conn;
    QString log;
    bool recording = false; // whether the recording could be started
    QByteArray received;    // every byte the transport delivered
};

} // namespace gnss::link::test
