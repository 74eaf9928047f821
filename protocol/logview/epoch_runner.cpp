#include "logview/epoch_runner.h"

#include "state/log_scan.h"

#include <algorithm>
#include <cmath>

namespace gnss::logview {

std::int64_t daysFromCivil(int y, int m, int d) {
    y -= m <= 2;
    const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
    const unsigned yoe = static_cast<unsigned>(y - era * 400);
    const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + static_cast<unsigned>(d) - 1;
    const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

EpochRunner::EpochRunner(const DialectRegistry &registry, const DecoderOptions &options,
                         const char *base, std::size_t checkpointEvery, Sinks sinks)
    : registry_(registry), options_(options), base_(base),
      every_(std::max<std::size_t>(1, checkpointEvery)), sinks_(std::move(sinks)),
      decoder_(std::make_unique<StreamDecoder>(registry, options)) {
    tracker_ = StateTracker(decoder_->dialect());
}

void EpochRunner::restore(const Checkpoint &from) {
    decoder_ = std::make_unique<StreamDecoder>(registry_, options_);
    if (decoder_->dialect() != from.dialect) decoder_->setDialect(from.dialect);
    framer_ = Framer();
    tracker_ = from.tracker;
    carry_ = from.carry;
    // The counts of the epoch in progress continue from the checkpoint's.
    skippedBase_ = 0 - carry_.junkBytes;
    truncatedBase_ = 0 - carry_.truncated;
    carry_.junkBytes = carry_.truncated = 0;
    end_ = from.resume;
    checkpointDue_ = false;
}

Checkpoint EpochRunner::save(std::uint64_t resume) const {
    Checkpoint c;
    c.resume = resume;
    c.dialect = decoder_->dialect();
    c.tracker = tracker_;
    c.carry = carry_;
    const FramerStats &f = framer_.stats();
    c.carry.junkBytes = f.bytesSkipped - skippedBase_;
    c.carry.truncated = f.truncated + f.tooLong + f.binaryAborted - truncatedBase_;
    return c;
}

bool EpochRunner::feed(std::string_view bytes, const std::atomic<bool> *cancel,
                       std::atomic<std::uint64_t> *progress) {
    // Pieces of a few MB, cut at a line end (so that every line is whole in one feed and stays a
    // view into the mapping): between them, cancel is looked at and progress reported.
    constexpr std::size_t kStep = 4 << 20;
    while (!bytes.empty()) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return false;
        std::size_t n = bytes.size();
        if (n > kStep) {
            const std::size_t end = lineEndAfter(bytes, kStep);
            n = end == std::string_view::npos ? bytes.size() : end;
        }
        chunkEnd_ = bytes.data() + n;
        framer_.feed(bytes.substr(0, n), [this](std::string_view line) { onLine(line); });
        end_ = static_cast<std::uint64_t>(bytes.data() + n - base_);
        if (progress) progress->fetch_add(n, std::memory_order_relaxed);
        bytes.remove_prefix(n);
    }
    return true;
}

void EpochRunner::finish() {
    framer_.finish();
    tracker_.flush([this](const ReceiverState &s) { completeEpoch(s); });
}

void EpochRunner::onLine(std::string_view line) {
    lineStart_ = static_cast<std::uint64_t>(line.data() - base_);
    decoder_->decodeLine(line, [this](const SentenceEvent &ev) { onEvent(ev); });
    if (checkpointDue_) {
        checkpointDue_ = false;
        // Resume after the line's terminator (both bytes of a CR LF), where the framer is
        // between sentences with nothing pending.
        const char *t = line.data() + line.size();
        std::uint64_t resume = lineStart_ + line.size() + 1;
        if (*t == '\r' && t + 1 < chunkEnd_ && t[1] == '\n') ++resume;
        if (sinks_.onCheckpoint) sinks_.onCheckpoint(save(resume));
    }
}

std::uint8_t EpochRunner::dialectIndex(const Dialect *d) const {
    const auto all = registry_.dialects();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (all[i] == d) return static_cast<std::uint8_t>(std::min<std::size_t>(i + 1, 255));
    return 0;
}

void EpochRunner::onEvent(const SentenceEvent &ev) {
    if (ev.message) {
        tracker_.setDialect(decoder_->dialect());
        tracker_.add(ev.sentence, *ev.message, ev.dialect,
                     [this](const ReceiverState &s) { completeEpoch(s); });
        // A receiver family's own sentence (not a standard one it reads its own way, which is
        // the family's only where it is the dialect preferred).
        if (ev.dialect && ev.sentence.checksum() != ChecksumStatus::Bad &&
            registry_.lookup(ev.sentence.address(), nullptr).dialect == ev.dialect)
            carry_.lastVendor = dialectIndex(ev.dialect);
    } else if (!ev.unknown && ev.sentence.checksum() != ChecksumStatus::Bad) {
        ++carry_.decodeErrors;
    }
    if (ev.sentence.checksum() == ChecksumStatus::Bad) ++carry_.checksumErrors;
}

void EpochRunner::completeEpoch(const ReceiverState &state) {
    const Epoch &e = state.epoch;
    EpochRecord r;
    r.offset = carry_.epochStart;
    std::uint32_t flags = 0;
    if (e.time) {
        const std::int64_t ms = e.time->nanos / 1'000'000;
        flags |= kTimeKnown;
        if (e.date && e.date->month >= 1 && e.date->month <= 12) {
            r.utcMs = daysFromCivil(e.date->year, e.date->month, e.date->day) * 86'400'000 + ms;
            flags |= kDateKnown;
        } else {
            r.utcMs = ms;
        }
    }
    r.fix = static_cast<std::uint8_t>(e.fix);
    if (e.lat && e.lon) {
        r.lat = *e.lat;
        r.lon = *e.lon;
    }
    if (e.altMsl) r.altMsl = static_cast<float>(*e.altMsl);
    if (e.hdop) r.hdop = static_cast<float>(*e.hdop);
    if (e.sogKnots) r.speed = static_cast<float>(*e.sogKnots * (1852.0 / 3600.0));
    if (e.satsUsed) r.sats = static_cast<std::uint8_t>(std::clamp(*e.satsUsed, 0, 254));
    int snrSum = 0, snrCount = 0;
    for (const SatelliteInView &s : e.satellites)
        if (s.snr) {
            snrSum += *s.snr;
            ++snrCount;
        }
    if (snrCount > 0)
        r.snr = static_cast<std::uint8_t>(std::clamp((snrSum + snrCount / 2) / snrCount, 0, 254));
    if (state.rtk.baseStationId)
        r.station = *state.rtk.baseStationId;
    else if (e.dgpsStation)
        r.station = *e.dgpsStation;
    if (state.jamming) r.jamming = *state.jamming ? 2 : 1;
    r.dialect = carry_.lastVendor;
    // A new time mark: the list grew, or its latest entry is another event.
    if (!state.timeMarks.empty()) {
        const auto &m = state.timeMarks.back();
        const std::uint64_t sig = (static_cast<std::uint64_t>(state.timeMarks.size()) << 40) ^
                                  static_cast<std::uint64_t>(m.counter.value_or(-1));
        if (sig != carry_.markSignature) flags |= kTimeMark;
        carry_.markSignature = sig;
    }
    const FramerStats &f = framer_.stats();
    const std::uint64_t junk = f.bytesSkipped - skippedBase_;
    const std::uint64_t cut = f.truncated + f.tooLong + f.binaryAborted - truncatedBase_;
    skippedBase_ = f.bytesSkipped;
    truncatedBase_ = f.truncated + f.tooLong + f.binaryAborted;
    if (junk) flags |= kJunk;
    if (cut) flags |= kTruncatedLines;
    if (carry_.checksumErrors) flags |= kChecksumErrors;
    if (carry_.decodeErrors) flags |= kDecodeErrors;
    r.checksumErrors =
            static_cast<std::uint8_t>(std::min<std::uint32_t>(carry_.checksumErrors, 255));
    r.flags = static_cast<std::uint16_t>(flags);
    carry_.checksumErrors = carry_.decodeErrors = 0;

    ++carry_.emitted;
    carry_.epochStart = lineStart_;
    if (carry_.emitted % every_ == 0) checkpointDue_ = true;
    if (sinks_.onEpoch) sinks_.onEpoch(std::move(r), state);
}

} // namespace gnss::logview
