#include "corrections/raw_correction_source.h"

namespace gnss::corrections {

void RawCorrectionSource::deliverReadsOf(QIODevice &device) {
    connect(&device, &QIODevice::readyRead, this, [this, &device] {
        if (closing_) return;
        const QByteArray bytes = device.readAll();
        if (bytes.isEmpty() || state() != State::Receiving) return;
        if (bytesReceived() == 0) setStatus(tr("Receiving RTCM from %1").arg(description()));
        deliver(bytes);
    });
}

} // namespace gnss::corrections
