#include "link/link_opener.h"

#include "core/baud_rates.h"
#include "link/sentence_stream.h"

#include <QStringList>

namespace gnss::link {

LinkOpener::LinkOpener(const TransportFactory &factory, const DialectRegistry &registry,
                       QObject *parent)
    : QObject(parent), factory_(factory), registry_(registry) {}

LinkOpener::~LinkOpener() {
    cancel();
}

QString LinkOpener::attemptText(const BaudAttempt &a) {
    if (a.validSentences > 0) return tr("%1 (valid NMEA)").arg(a.baud);
    if (a.rtcmFrames > 0) return tr("%1 (valid RTCM 3)").arg(a.baud);
    if (a.bytes == 0) return tr("%1 (no data)").arg(a.baud);
    return tr("%1 (data, no valid sentence)").arg(a.baud);
}

QString LinkOpener::attemptsText(const BaudDetection &d, int count) {
    QStringList tried;
    for (const auto &a : d.tried) {
        if (count >= 0 && tried.size() >= count) break;
        tried << attemptText(a);
    }
    return tried.join(QStringLiteral(", "));
}

void LinkOpener::start(const SourceSpec &spec, DecoderOptions options) {
    cancel();
    spec_ = spec;
    options_ = std::move(options);
    detection_ = {};
    connection_.reset();
    QString error;
    std::unique_ptr<Transport> transport = factory_.make(spec, &error);
    if (!transport) {
        emit failed(error);
        return;
    }
    if (spec.kind != SourceSpec::Kind::Serial || spec.baud > 0)
        return finishWith(std::move(transport));

    if (!transport->open()) {
        emit failed(transport->errorString());
        return;
    }
    port_ = std::move(transport);
    // The decoder of the port while its speed is unknown; the connection has its own from the
    // moment it takes the port over (every byte is decoded once).
    detectingStream_ = std::make_unique<SentenceStream>(port_.get(), registry_);
    detector_ = std::make_unique<BaudDetector>(detectingStream_.get());
    if (listenMs_ > 0) detector_->setListenMs(listenMs_);
    if (!candidates_.isEmpty()) detector_->setCandidates(candidates_);
    connect(detector_.get(), &BaudDetector::tryingRate, this, &LinkOpener::tryingRate);
    connect(detector_.get(), &BaudDetector::finished, this, &LinkOpener::onDetection);
    detector_->start();
}

void LinkOpener::cancel() {
    if (detector_) {
        detector_->disconnect(this); // stopped on purpose: nothing to report
        detector_->cancel();
    }
    detector_.reset();
    detectingStream_.reset();
    port_.reset();
}

void LinkOpener::onDetection(const BaudDetection &result) {
    detection_ = result;
    // This may run inside the detection stream's own signal: stream and detector go later,
    // deaf from now on (the connection's stream decodes what follows).
    std::unique_ptr<Transport> port = std::move(port_);
    QObject::disconnect(port.get(), nullptr, detectingStream_.get(), nullptr);
    detector_->disconnect(this);
    detector_.release()->deleteLater();
    detectingStream_.release()->deleteLater();
    if (!result.found) {
        port->close();
        port.release()->deleteLater();
        emit failed(result.error);
        return;
    }
    finishWith(std::move(port));
}

void LinkOpener::finishWith(std::unique_ptr<Transport> transport) {
    DecoderOptions options = options_;
    if (spec_.kind == SourceSpec::Kind::Simulator && options.dialect == "auto")
        options.dialect = spec_.name.toStdString(); // the simulated receiver's own dialect
    connection_ = std::make_unique<Connection>(std::move(transport), registry_, options);
    emit ready();
}

} // namespace gnss::link
