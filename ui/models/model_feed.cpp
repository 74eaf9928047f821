#include "models/model_feed.h"
#include "models/refresh_intervals.h"

#include "config/refusal_text.h"

#include <QDateTime>

namespace gnss::ui {

ModelFeed::ModelFeed(const DialectRegistry &registry, SessionModels models, QObject *parent)
    : QObject(parent), registry_(registry), models_(models) {
    reset();
    refreshTimer_.setInterval(kLiveRefreshMs);
    connect(&refreshTimer_, &QTimer::timeout, this, &ModelFeed::refresh);
    refreshTimer_.start();
}

void ModelFeed::reset() {
    counterSource_ = nullptr;
    tracker_ = std::make_unique<StateTracker>(nullptr);
    lastDialect_ = nullptr;
    counters_ = {};
    bytesAtLastRate_ = sentencesAtLastRate_ = 0;
    lastRateMs_ = QDateTime::currentMSecsSinceEpoch();
    if (models_.state) models_.state->clear();
    if (models_.satellites) models_.satellites->clear();
    if (models_.messages) models_.messages->clear();
    if (models_.console) models_.console->clear();
    emit dialectChanged(lastDialect_);
}

void ModelFeed::noteBytes(const QByteArray &bytes) {
    if (models_.console) models_.console->appendRaw(bytes);
}

void ModelFeed::consume(const SentenceEvent &ev, const Dialect *dialect) {
    if (dialect != lastDialect_) {
        lastDialect_ = dialect;
        tracker_->setDialect(dialect);
        // The satellites seen so far were numbered without the dialect (a GeoS-5's Galileo at
        // 101-136 read as satellites of no known system): kept as "recently lost", they would
        // stand beside the same satellites renamed for ten seconds.
        tracker_->forgetSatellites();
        if (models_.satellites) models_.satellites->clear();
        emit dialectChanged(dialect);
    }
    const Sentence &s = ev.sentence;
    if (models_.console && !models_.console->paused()) {
        ConsoleLine l;
        l.ms = QDateTime::currentMSecsSinceEpoch();
        l.text = QByteArray(s.line().data(), qsizetype(s.line().size()));
        l.address = QByteArray(s.address().data(), qsizetype(s.address().size()));
        l.checksumBad = s.checksum() == ChecksumStatus::Bad;
        if (!ev.message) {
            // The decoder's word in the user's language (core/refusal.h).
            const QString why = config::refusalText(ev.error, ev.problem);
            if (ev.unknown)
                l.note = why; // not decoded, but nothing wrong with the line
            else
                l.error = why;
        }
        models_.console->append(std::move(l));
    }
    if (!ev.message) return;
    tracker_->add(s, *ev.message, ev.dialect, [this](const ReceiverState &st) {
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        if (models_.satellites) models_.satellites->update(st.epoch, now);
        if (models_.state) models_.state->publish(st, QDateTime::fromMSecsSinceEpoch(now, Qt::UTC));
    });
}

void ModelFeed::noteSent(const QByteArray &sentence) {
    if (!models_.console) return;
    ConsoleLine l;
    l.ms = QDateTime::currentMSecsSinceEpoch();
    l.text = sentence.trimmed();
    const int comma = l.text.indexOf(',');
    const int star = l.text.indexOf('*');
    const int end = comma >= 0 ? comma : (star >= 0 ? star : l.text.size());
    l.address = l.text.mid(1, end - 1);
    l.sent = true;
    models_.console->append(std::move(l));
}

void ModelFeed::updateCounts() {
    // The decoder's own counts: one place, whatever listens to it.
    if (!counterSource_) return;
    LinkCounters c = counters_;
    c.bytes = counterSource_->framerStats().bytesIn;
    c.skippedBytes = counterSource_->junkBytes();
    c.rtcmFrames = counterSource_->rtcmStats().frames;
    c.sentences = c.checksumErrors = c.decodeErrors = 0;
    for (const AddressStats &a : counterSource_->addressStats()) {
        c.sentences += a.sentences;
        c.checksumErrors += a.checksumBad;
        c.decodeErrors += a.decodeErrors;
    }
    counters_ = c;
}

void ModelFeed::refresh() {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    if (models_.console) models_.console->flush();
    updateCounts();
    if (models_.messages && counterSource_)
        models_.messages->refresh(counterSource_->addressStats(), now);
    if (now - lastRateMs_ >= 1000) {
        const double dt = double(now - lastRateMs_) / 1000.0;
        counters_.bytesPerSecond = double(counters_.bytes - bytesAtLastRate_) / dt;
        counters_.sentencesPerSecond = double(counters_.sentences - sentencesAtLastRate_) / dt;
        bytesAtLastRate_ = counters_.bytes;
        sentencesAtLastRate_ = counters_.sentences;
        lastRateMs_ = now;
    }
    emit countersChanged();
}

} // namespace gnss::ui
