#pragma once
// EpochRunner: decodes a stretch of a mapped log front to back, as StreamDecoder + StateTracker
// do, and turns each navigation epoch into an EpochRecord; every N epochs it saves a Checkpoint
// (everything needed to go on decoding from there as if from the start of the log).
//
// Lines are handed to the decoder as views into the mapping, so each epoch knows its file offset.
// An epoch starts at the line that closed the one before (its first timed sentence), so epochs
// tile the file: epoch k is [offset_k, offset_k+1).
#include "core/framer.h"
#include "core/stream_decoder.h"
#include "logview/epoch_record.h"
#include "state/state_tracker.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

namespace gnss::logview {

// What the runner carries from one line to the next besides the decoder's dialect and the
// tracker: where the epoch in progress started, and what its lines have shown so far.
struct RunnerCarry {
    std::uint64_t emitted = 0;       // epochs completed so far (the one in progress has this index)
    std::uint64_t epochStart = 0;    // file offset where the epoch in progress started
    std::uint8_t lastVendor = 0;     // EpochRecord::dialect of the last vendor sentence heard
    std::uint64_t markSignature = 0; // the receiver's latest time mark, to see a new one
    std::uint32_t checksumErrors = 0, decodeErrors = 0; // in the epoch in progress
    std::uint64_t junkBytes = 0, truncated = 0;         // in the epoch in progress

    // Same future, whatever the epoch count.
    bool sameAs(const RunnerCarry &o) const {
        return epochStart == o.epochStart && lastVendor == o.lastVendor &&
               markSignature == o.markSignature && checksumErrors == o.checksumErrors &&
               decodeErrors == o.decodeErrors && junkBytes == o.junkBytes &&
               truncated == o.truncated;
    }
};

// The decoding state at a line boundary: decode on from `resume` with it and every epoch comes
// out as from a front-to-back decode of the whole log.
struct Checkpoint {
    std::uint64_t resume = 0;         // file offset of the next byte to decode
    const Dialect *dialect = nullptr; // the decoder's dialect (chosen or recognised)
    StateTracker tracker;
    RunnerCarry carry;

    bool sameFuture(const Checkpoint &o) const {
        return resume == o.resume && dialect == o.dialect && carry.sameAs(o.carry) &&
               tracker.sameFuture(o.tracker);
    }
};

class EpochRunner {
public:
    struct Sinks {
        // Each completed epoch, with the receiver state a front-to-back decode has there.
        std::function<void(EpochRecord &&, const ReceiverState &)> onEpoch;
        // A checkpoint every `checkpointEvery` epochs (when the count is a multiple of it).
        std::function<void(Checkpoint &&)> onCheckpoint;
    };

    // `base` is the byte at file offset 0 (the mapping's start): every line fed must lie in it.
    EpochRunner(const DialectRegistry &registry, const DecoderOptions &options, const char *base,
                std::size_t checkpointEvery, Sinks sinks);

    // Starts from a checkpoint (or, for the start of a log, Checkpoint{resume = start}).
    void restore(const Checkpoint &from);
    // The state now, as a checkpoint resuming at `resume` (the next byte that will be fed).
    Checkpoint save(std::uint64_t resume) const;

    // Decodes `bytes` (a view into the mapping, starting at a line boundary). Stops early, between
    // lines, when `cancel` becomes true (returns false then). `progress` gets the bytes done.
    bool feed(std::string_view bytes, const std::atomic<bool> *cancel = nullptr,
              std::atomic<std::uint64_t> *progress = nullptr);
    // End of the data: the epoch in progress is completed (the tracker is flushed).
    void finish();

    std::uint64_t emitted() const { return carry_.emitted; }
    // File offset just past the last byte fed (a line end after a cancelled feed()).
    std::uint64_t fedEnd() const { return end_; }
    const FramerStats &framerStats() const { return framer_.stats(); }
    const std::vector<AddressStats> &addressStats() const { return decoder_->addressStats(); }
    const Dialect *dialect() const { return decoder_->dialect(); }

private:
    void onLine(std::string_view line);
    void onEvent(const SentenceEvent &ev);
    void completeEpoch(const ReceiverState &state);
    std::uint8_t dialectIndex(const Dialect *d) const;

    const DialectRegistry &registry_;
    DecoderOptions options_;
    const char *base_;
    std::size_t every_;
    Sinks sinks_;
    std::unique_ptr<StreamDecoder> decoder_;
    Framer framer_;
    StateTracker tracker_;
    RunnerCarry carry_;
    std::uint64_t lineStart_ = 0;
    std::uint64_t skippedBase_ = 0, truncatedBase_ = 0; // framer counts at the last epoch's end
    bool checkpointDue_ = false;
    std::uint64_t end_ = 0;          // file offset just past the last byte fed
    const char *chunkEnd_ = nullptr; // end of the bytes being fed
};

// Days since 1970-01-01 of a civil date (proleptic Gregorian).
std::int64_t daysFromCivil(int year, int month, int day);

} // namespace gnss::logview
