#pragma once
// Test helper: decode one line through the real StreamDecoder and return the message as JSON
// (the same JSON `gnss-cli decode` prints), or the error.
#include "core/stream_decoder.h"
#include "dialects.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

namespace gnss::test {

struct Decoded {
    bool ok = false;
    QJsonObject data;
    QString error;
    QString checksum;
};

inline Decoded decodeOne(const QString &line, DecoderOptions opts = {}) {
    static const DialectRegistry registry = makeBuiltinRegistry();
    StreamDecoder dec(registry, std::move(opts));
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

} // namespace gnss::test
