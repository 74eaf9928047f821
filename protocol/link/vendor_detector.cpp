#include "link/vendor_detector.h"

#include "core/json_writer.h"
#include "link/command_queue.h"
#include "link/sentence_stream.h"
#include "link/transport.h"
#include "state/receiver_state.h"

namespace gnss::link {

VendorDetector::VendorDetector(SentenceStream *stream, QObject *parent)
    : QObject(parent), stream_(stream), transport_(stream ? stream->transport() : nullptr) {
    timer_.setSingleShot(true);
}

VendorDetector::~VendorDetector() = default;

void VendorDetector::start() {
    result_ = {};
    if (!stream_ || !transport_ || !transport_->isOpen()) {
        result_.error = tr("Vendor detection needs an open link");
        emit finished(result_);
        return;
    }
    running_ = true;
    sawValid_ = false;
    probing_ = passive_ = nullptr;
    eventConnection_ =
            connect(stream_, &SentenceStream::sentenceDecoded, this, &VendorDetector::onEvent);
    timer_.disconnect();
    connect(&timer_, &QTimer::timeout, this, &VendorDetector::passiveDone);
    timer_.start(passiveMs_);
}

void VendorDetector::onEvent(const SentenceEvent &ev) {
    if (!running_) return;
    const Sentence &s = ev.sentence;
    const bool checksumOk =
            s.checksum() == ChecksumStatus::Ok ||
            (s.checksum() == ChecksumStatus::Missing && ev.dialect && ev.dialect->checksumOptional);
    if (!checksumOk) return;
    sawValid_ = true;
    if (!probing_) return;
    const ReplyRule *rule = CommandQueue::findRule(probing_->replyRules, probeSentence_);
    if (!rule || !rule->classify) return;
    if (rule->classify(probeSentence_, s, progress_) != ReplyVerdict::Accepted) return;
    result_.found = true;
    result_.dialect = QString::fromUtf8(probing_->id.data(), probing_->id.size());
    result_.dialectName =
            QString::fromUtf8(probing_->displayName.data(), probing_->displayName.size());
    result_.method =
            probing_ == passive_ ? QStringLiteral("passive+active") : QStringLiteral("active");
    result_.reply = QString::fromLatin1(s.line().data(), s.line().size());
    if (ev.message) {
        std::string json;
        JsonWriter w(json);
        ev.message->writeJson(w);
        result_.replyJson = QString::fromStdString(json);
        // The dialect's own reading of its reply, the one the views show.
        ReceiverState st;
        if (probing_->updateState && probing_->updateState(*ev.message, st)) {
            result_.model = QString::fromStdString(st.identity.model);
            result_.firmware = QString::fromStdString(st.identity.firmware);
            if (!st.identity.hardware.empty())
                result_.firmware +=
                        QStringLiteral(" (%1)").arg(QString::fromStdString(st.identity.hardware));
        }
    }
    done();
}

void VendorDetector::passiveDone() {
    passive_ = stream_ ? stream_->dialect() : nullptr;
    toProbe_.clear();
    if (passive_) {
        result_.found = true;
        result_.dialect = QString::fromUtf8(passive_->id.data(), passive_->id.size());
        result_.dialectName =
                QString::fromUtf8(passive_->displayName.data(), passive_->displayName.size());
        result_.method = QStringLiteral("passive");
        if (!passive_->probeCommand.empty()) toProbe_.push_back(passive_);
    } else {
        for (const Dialect *d : stream_->registry().dialects())
            if (!d->probeCommand.empty()) toProbe_.push_back(d);
    }
    if (!active_ || !transport_->canWrite()) toProbe_.clear();
    probeNext();
}

void VendorDetector::probeNext() {
    if (!running_) return;
    if (toProbe_.empty()) {
        probing_ = nullptr;
        return done();
    }
    probing_ = toProbe_.front();
    toProbe_.erase(toProbe_.begin());
    probeLine_.assign(probing_->probeCommand);
    probeSentence_.parse(probeLine_);
    progress_ = {};
    transport_->write(QByteArray::fromStdString(probeLine_) + "\r\n");
    timer_.disconnect();
    connect(&timer_, &QTimer::timeout, this, &VendorDetector::probeNext);
    timer_.start(probeTimeoutMs_);
}

void VendorDetector::done() {
    running_ = false;
    timer_.stop();
    disconnect(eventConnection_);
    if (!result_.found) {
        if (sawValid_) {
            const Dialect *nmea = stream_ ? stream_->registry().find("nmea") : nullptr;
            result_.found = true;
            result_.dialect = QStringLiteral("nmea");
            result_.dialectName =
                    nmea ? QString::fromUtf8(nmea->displayName.data(), nmea->displayName.size())
                         : QStringLiteral("NMEA-0183");
            result_.method = QStringLiteral("passive");
        } else {
            result_.error = tr("No valid sentence and no answer to any probe: check the baud "
                               "rate and that the receiver sends NMEA");
        }
    }
    emit finished(result_);
}

} // namespace gnss::link
