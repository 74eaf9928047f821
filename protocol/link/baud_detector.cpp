#include "link/baud_detector.h"

#include "core/baud_rates.h"
#include "core/sentence.h"
#include "link/sentence_stream.h"
#include "link/transport.h"

#include <QStringList>

namespace gnss::link {

BaudDetector::BaudDetector(SentenceStream *stream, QObject *parent)
    : QObject(parent), stream_(stream), transport_(stream ? stream->transport() : nullptr) {
    timer_.setSingleShot(true);
}

QList<int> BaudDetector::likelyRates(int current) {
    QList<int> rates(kDetectionBauds.begin(), kDetectionBauds.end());
    if (current > 0) {
        rates.removeAll(current);
        rates.prepend(current);
    }
    return rates;
}

void BaudDetector::start() {
    result_ = {};
    if (candidates_.isEmpty()) candidates_ = likelyRates(transport_ ? transport_->baud() : 0);
    if (!stream_ || !transport_ || !transport_->isOpen() || transport_->baud() <= 0) {
        result_.error = tr("Baud detection needs an open serial port");
        emit finished(result_);
        return;
    }
    running_ = true;
    index_ = -1;
    // Bytes are counted from the transport (a rate that gives bytes but no sentence says
    // something); sentences from the stream.
    bytesConnection_ = connect(transport_, &Transport::bytesReceived, this, &BaudDetector::onBytes);
    eventConnection_ =
            connect(stream_, &SentenceStream::sentenceDecoded, this, &BaudDetector::onEvent);
    frameConnection_ = connect(stream_, &SentenceStream::rtcmFrame, this, &BaudDetector::onFrame);
    tryNext();
}

void BaudDetector::cancel() {
    if (!running_) return;
    result_.error = tr("Baud detection cancelled");
    done(false);
}

void BaudDetector::tryNext() {
    if (!running_) return;
    if (++index_ >= candidates_.size()) return done(false);
    const int baud = candidates_[index_];
    result_.tried.push_back({baud, 0, 0, 0});
    emit tryingRate(baud);
    listening_ = false;
    transport_->setBaud(baud);
    // Bytes already on their way were sent at the old speed: let them pass, then drop them.
    timer_.disconnect();
    connect(&timer_, &QTimer::timeout, this, [this] {
        if (!running_) return;
        transport_->discardInput();
        stream_->resetFraming();
        listening_ = true;
        if (!probe_.isEmpty()) transport_->write(probe_ + "\r\n");
        timer_.disconnect();
        connect(&timer_, &QTimer::timeout, this, &BaudDetector::rateDone);
        timer_.start(listenMs_);
    });
    timer_.start(settleMs_);
}

void BaudDetector::onBytes(const QByteArray &bytes) {
    if (!running_ || !listening_ || result_.tried.empty()) return;
    result_.tried.back().bytes += bytes.size();
}

void BaudDetector::onEvent(const SentenceEvent &event) {
    if (!running_ || !listening_ || result_.tried.empty()) return;
    BaudAttempt &a = result_.tried.back();
    if (event.sentence.checksum() == ChecksumStatus::Ok)
        ++a.validSentences;
    else
        ++a.badSentences;
    if (a.validSentences >= required_) {
        timer_.stop();
        result_.baud = a.baud;
        done(true);
    }
}

void BaudDetector::onFrame() {
    // A frame's CRC-24Q at a wrong speed is as unlikely as a sentence's checksum: as good.
    if (!running_ || !listening_ || result_.tried.empty()) return;
    BaudAttempt &a = result_.tried.back();
    if (++a.rtcmFrames >= required_) {
        timer_.stop();
        result_.baud = a.baud;
        done(true);
    }
}

void BaudDetector::rateDone() {
    tryNext();
}

void BaudDetector::done(bool found) {
    running_ = false;
    listening_ = false;
    timer_.stop();
    disconnect(bytesConnection_);
    disconnect(eventConnection_);
    disconnect(frameConnection_);
    result_.found = found;
    if (!found && result_.error.isEmpty()) {
        QStringList rates;
        qint64 bytes = 0;
        for (const auto &a : result_.tried) {
            rates << QString::number(a.baud);
            bytes += a.bytes;
        }
        const QString list = rates.join(QStringLiteral(", "));
        result_.error =
                bytes == 0
                        ? tr("No data at any rate (tried %1 baud): check the cable, the port and "
                             "that the receiver is powered")
                                  .arg(list)
                        : tr("Data but never a valid sentence or RTCM 3 frame at %1 baud: wrong "
                             "framing (data bits, parity, stop bits) or the receiver is not "
                             "sending NMEA or RTCM?")
                                  .arg(list);
        // Leave the port where it started.
        if (transport_ && !result_.tried.empty()) transport_->setBaud(result_.tried.front().baud);
    }
    emit finished(result_);
}

} // namespace gnss::link
