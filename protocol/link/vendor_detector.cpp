#include "vendor_detector.h"

#include "command_queue.h"
#include "core/json_writer.h"
#include "state/receiver_state.h"
#include "transport.h"

#include <QJsonDocument>
#include <QJsonObject>

namespace gnss::link {

VendorDetector::VendorDetector(Transport *transport, const DialectRegistry &registry,
                               QObject *parent)
    : QObject(parent), transport_(transport), registry_(registry) {
    timer_.setSingleShot(true);
}

VendorDetector::~VendorDetector() = default;

void VendorDetector::start() {
    result_ = {};
    if (!transport_ || !transport_->isOpen()) {
        result_.error = tr("Vendor detection needs an open link");
        emit finished(result_);
        return;
    }
    decoder_ = std::make_unique<StreamDecoder>(registry_);
    running_ = true;
    sawValid_ = false;
    probing_ = passive_ = nullptr;
    bytesConnection_ =
            connect(transport_, &Transport::bytesReceived, this, &VendorDetector::onBytes);
    timer_.disconnect();
    connect(&timer_, &QTimer::timeout, this, &VendorDetector::passiveDone);
    timer_.start(passiveMs_);
}

void VendorDetector::onBytes(const QByteArray &bytes) {
    if (!running_) return;
    decoder_->feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
                   [this](const SentenceEvent &ev) { onEvent(ev); });
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
        // The dialect's own reading of its reply (the one the views show); field names as a
        // fallback for a dialect without one.
        ReceiverState st;
        if (probing_->updateState && probing_->updateState(*ev.message, st) &&
            !st.identity.model.empty()) {
            result_.model = QString::fromStdString(st.identity.model);
            result_.firmware = QString::fromStdString(st.identity.firmware);
            if (!st.identity.hardware.empty())
                result_.firmware +=
                        QStringLiteral(" (%1)").arg(QString::fromStdString(st.identity.hardware));
        } else {
            readIdentity(result_.replyJson, result_);
        }
    }
    done();
}

void VendorDetector::passiveDone() {
    passive_ = decoder_->dialect();
    toProbe_.clear();
    if (passive_) {
        result_.found = true;
        result_.dialect = QString::fromUtf8(passive_->id.data(), passive_->id.size());
        result_.dialectName =
                QString::fromUtf8(passive_->displayName.data(), passive_->displayName.size());
        result_.method = QStringLiteral("passive");
        if (!passive_->probeCommand.empty()) toProbe_.push_back(passive_);
    } else {
        for (const Dialect *d : registry_.dialects())
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
    disconnect(bytesConnection_);
    if (!result_.found) {
        if (sawValid_) {
            const Dialect *nmea = registry_.find("nmea");
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

void VendorDetector::readIdentity(const QString &replyJson, VendorIdentity &id) {
    const QJsonObject o = QJsonDocument::fromJson(replyJson.toUtf8()).object();
    auto text = [&](const char *key) { return o.value(QLatin1String(key)).toString(); };
    QString model = text("model");
    if (model.isEmpty()) model = text("receiver_name");
    if (model.isEmpty() && !text("device").isEmpty())
        model = (text("manufacturer") + QLatin1Char(' ') + text("device")).trimmed();
    QString firmware = text("firmware");
    if (firmware.isEmpty() && !text("rtk_fw").isEmpty()) {
        firmware = text("rtk_fw");
        if (!text("csm_fw").isEmpty())
            firmware += QStringLiteral(" (%1 %2)")
                                .arg(text("csm_hw"), text("csm_fw"))
                                .replace(QStringLiteral("( "), QStringLiteral("("));
    }
    if (firmware.isEmpty()) firmware = text("version");
    id.model = model;
    id.firmware = firmware;
}

} // namespace gnss::link
