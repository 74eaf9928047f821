#include "link/sentence_stream.h"

#include "link/transport.h"

namespace gnss::link {

SentenceStream::SentenceStream(Transport *transport, const DialectRegistry &registry,
                               DecoderOptions options, QObject *parent)
    : QObject(parent), transport_(transport), decoder_(registry, std::move(options)) {
    announced_ = decoder_.dialect();
    decoder_.setFrameHandler([this](const rtcm::RtcmFrame &f) {
        emit rtcmFrame(f.messageNumber(), QByteArray(reinterpret_cast<const char *>(f.bytes.data()),
                                                     qsizetype(f.bytes.size())));
    });
    if (transport) connect(transport, &Transport::bytesReceived, this, &SentenceStream::feed);
}

void SentenceStream::feed(const QByteArray &bytes) {
    bytes_ += static_cast<quint64>(bytes.size());
    decoder_.feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
                  [this](const SentenceEvent &ev) {
                      // The dialect is announced before the sentence that revealed it.
                      if (decoder_.dialect() != announced_) announceDialect();
                      emit sentenceDecoded(ev);
                  });
    if (decoder_.dialect() != announced_) announceDialect();
}

void SentenceStream::setDialect(const Dialect *dialect) {
    decoder_.setDialect(dialect);
    if (decoder_.dialect() != announced_) announceDialect();
}

void SentenceStream::resetFraming() {
    decoder_.resetFraming();
}

void SentenceStream::finish() {
    decoder_.finish();
}

void SentenceStream::announceDialect() {
    announced_ = decoder_.dialect();
    emit dialectChanged(announced_);
}

} // namespace gnss::link
