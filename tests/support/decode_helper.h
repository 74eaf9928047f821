#pragma once
// Test helper: decode one line through the real StreamDecoder and return the message as JSON
// (the same JSON `gnss-cli decode` prints), or the error.
#include "builtin_registry.h"
#include "core/stream_decoder.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QTest>

#include <functional>
#include <string>
#include <vector>

namespace gnss::test {

struct Decoded {
    bool ok = false;
    QJsonObject data;
    QString error;
    QString checksum;
};

inline Decoded decodeOne(const QString &line, DecoderOptions opts = {}) {
    StreamDecoder dec(builtinRegistry(), std::move(opts));
    Decoded out;
    const std::string l = line.toStdString();
    dec.decodeLine(l, [&](const SentenceEvent &ev) {
        out.checksum = QString::fromStdString(std::string(toString(ev.sentence.checksum())));
        if (ev.message) {
            std::string json;
            JsonWriter w(json);
            ev.message->writeJson(w);
            out.ok = true;
            out.data = QJsonDocument::fromJson(QByteArray::fromStdString(json)).object();
        } else {
            out.error = QString::fromStdString(std::string(ev.error));
        }
    });
    return out;
}

// Decodes `line` under `dialect` and hands the message to `check` (the message refers to the
// line: it is only valid inside); the test fails if the checksum is off or nothing decodes.
inline void decodeWith(const char *dialect, const std::string &line,
                       const std::function<void(const Message &)> &check) {
    const DialectRegistry &registry = builtinRegistry();
    DecoderOptions o;
    o.dialect = dialect;
    StreamDecoder dec(registry, o);
    bool decoded = false;
    std::string error;
    dec.decodeLine(line, [&](const SentenceEvent &ev) {
        QCOMPARE(int(ev.sentence.checksum()), int(ChecksumStatus::Ok));
        if (ev.message) {
            decoded = true;
            check(*ev.message);
        } else {
            error = std::string(ev.error);
        }
    });
    QVERIFY2(decoded, (line + ": " + error).c_str());
}

// What `dialect`'s extractSettings reads from `line` (nothing when the line does not decode).
inline std::vector<KeyValue> extractedSettings(const char *dialect, const std::string &line) {
    const DialectRegistry &registry = builtinRegistry();
    DecoderOptions o;
    o.dialect = dialect;
    StreamDecoder dec(registry, o);
    const Dialect &d = *registry.find(dialect);
    std::vector<KeyValue> out;
    dec.decodeLine(line, [&](const SentenceEvent &ev) {
        if (ev.message) d.extractSettings(*ev.message, out);
    });
    return out;
}

} // namespace gnss::test
