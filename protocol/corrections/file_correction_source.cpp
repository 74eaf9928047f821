#include "corrections/file_correction_source.h"

#include <QFile>
#include <QFileInfo>

#include <cmath>

namespace gnss::corrections {

FileCorrectionSource::FileCorrectionSource(QString path, QObject *parent)
    : CorrectionSource(parent), path_(std::move(path)) {
    // A file has no connection to stall: its pauses are the recording's own.
    setStallTimeout(0);
    timer_.setSingleShot(true);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &FileCorrectionSource::sendDue);
}

FileCorrectionSource::~FileCorrectionSource() = default;

QString FileCorrectionSource::description() const {
    return QFileInfo(path_).fileName();
}

void FileCorrectionSource::setSpeed(double speed) {
    if (std::isfinite(speed) && speed > 0) speed_ = speed;
}

void FileCorrectionSource::openConnection() {
    closeConnection();
    QFile f(path_);
    if (!f.open(QIODevice::ReadOnly))
        return failed(tr("Cannot read %1: %2").arg(path_, f.errorString()), false);
    bytes_ = f.readAll();
    plan_ = planPlayback(std::string_view(bytes_.constData(), std::size_t(bytes_.size())));
    if (plan_.frames == 0) return failed(tr("%1 holds no RTCM 3 frames").arg(description()), false);
    next_ = 0;
    origin_ = 0;
    setReceiving(tr("Playing %1 (%2 frames, %3 s at speed %4)")
                         .arg(description())
                         .arg(plan_.frames)
                         .arg(plan_.durationMs() / 1000.0 / speed_, 0, 'f', 1)
                         .arg(speed_));
    clock_.start();
    sendDue();
}

void FileCorrectionSource::closeConnection() {
    timer_.stop();
}

void FileCorrectionSource::sendDue() {
    if (state() != State::Receiving) return;
    const double elapsed = static_cast<double>(clock_.nsecsElapsed()) / 1e6 * speed_;
    while (next_ < plan_.groups.size() &&
           origin_ + static_cast<double>(plan_.groups[next_].atMs) <= elapsed + 0.5) {
        const PlaybackGroup &g = plan_.groups[next_++];
        deliver(bytes_.mid(qsizetype(g.begin), qsizetype(g.end - g.begin)));
        if (state() != State::Receiving) return; // stopped by a receiver of dataReceived
    }
    if (next_ >= plan_.groups.size()) {
        if (!loop_) return finished(tr("Played %1 to the end").arg(description()));
        // Once more from the top, one second after the last group (as a base would go on).
        next_ = 0;
        origin_ += static_cast<double>(plan_.durationMs()) + 1000;
    }
    const double wait =
            (origin_ + static_cast<double>(plan_.groups[next_].atMs) - elapsed) / speed_;
    timer_.start(static_cast<int>(std::max(0.0, std::ceil(wait))));
}

} // namespace gnss::corrections
