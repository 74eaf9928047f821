#pragma once
// SentenceStream: the one decoder of a link. The transport's bytes are framed and decoded here
// once (NMEA, and RTCM 3 frames beside it), and every sentence (decoded, or with the reason it was
// not) is published to whoever listens: the command queue, the baud and vendor detectors, the
// settings engine, the views' session, the command line. Byte, sentence and error counts come from
// here only.
//
// A SentenceEvent refers to the line and the message only during the signal; listeners that
// keep something copy it. Connections must be direct (the default within one thread).
#include "core/stream_decoder.h"

#include <QObject>
#include <QPointer>

namespace gnss::link {

class Transport;

class SentenceStream : public QObject {
    Q_OBJECT
public:
    SentenceStream(Transport *transport, const DialectRegistry &registry,
                   DecoderOptions options = {}, QObject *parent = nullptr);

    Transport *transport() const { return transport_; }
    StreamDecoder &decoder() { return decoder_; }
    const StreamDecoder &decoder() const { return decoder_; }
    const DialectRegistry &registry() const { return decoder_.registry(); }
    // The dialect in force: chosen, or detected from the stream; nullptr while none is known.
    const Dialect *dialect() const { return decoder_.dialect(); }
    // Forces a dialect (after active detection); nullptr returns to detection from the stream.
    void setDialect(const Dialect *dialect);

    // Forgets a partly received line (after a baud switch: bytes at the old speed are noise).
    void resetFraming();
    // End of the stream or a drop: a partial line is counted as cut, not glued to what follows.
    void finish();
    quint64 bytesReceived() const { return bytes_; }

    // Decodes bytes that did not come from the transport (tests, a replay fed by hand).
    void feed(const QByteArray &bytes);

signals:
    void sentenceDecoded(const gnss::SentenceEvent &event);
    // The dialect in force changed (detected, forced, or back to unknown).
    void dialectChanged(const gnss::Dialect *dialect);
    // An RTCM 3 frame with a good CRC in the same bytes (a base that interleaves them, or a port
    // that carries RTCM only): its message number and the whole frame.
    void rtcmFrame(unsigned messageNumber, const QByteArray &frame);

private:
    void announceDialect();

    QPointer<Transport> transport_;
    StreamDecoder decoder_;
    quint64 bytes_ = 0;
    const Dialect *announced_ = nullptr;
};

} // namespace gnss::link
