#include "state/log_scan.h"

#include "state/epoch_assembler.h"

#include <atomic>
#include <thread>
#include <unordered_map>

namespace gnss {
namespace {

constexpr std::size_t kNoDetection = static_cast<std::size_t>(-1);

struct SegmentRun {
    FramerStats framer;
    std::vector<AddressStats> addresses;
    std::uint64_t epochs = 0;
    bool hasFirst = false;
    std::optional<TimeOfDay> firstEpochTime, lastEpochTime;
    const Dialect *initialDialect = nullptr;
    const Dialect *finalDialect = nullptr;
    std::size_t detectLineStart = kNoDetection; // where auto detection named the dialect
};

SegmentRun runSegment(std::string_view seg, const DialectRegistry &registry,
                      const DecoderOptions &options, const Dialect *forced) {
    DecoderOptions sentencesOnly = options; // RTCM is framed once over the whole log, below
    sentencesOnly.frameRtcm = false;
    StreamDecoder dec(registry, sentencesOnly);
    if (forced) dec.setDialect(forced);
    EpochAssembler assembler(dec.dialect());
    SegmentRun r;
    r.initialDialect = dec.dialect();
    auto onEpoch = [&](const Epoch &e) {
        ++r.epochs;
        if (!r.hasFirst) {
            r.hasFirst = true;
            r.firstEpochTime = e.time;
        }
        r.lastEpochTime = e.time;
    };
    const Dialect *seen = dec.dialect();
    // One feed of the whole segment: every line is a view into `seg`, so its offset is known.
    dec.feed(seg, [&](const SentenceEvent &ev) {
        if (dec.dialect() != seen) {
            if (r.detectLineStart == kNoDetection)
                r.detectLineStart =
                        static_cast<std::size_t>(ev.sentence.line().data() - seg.data());
            seen = dec.dialect();
        }
        if (ev.message) {
            assembler.setDialect(dec.dialect());
            assembler.add(ev.sentence, *ev.message, onEpoch);
        }
    });
    dec.finish();
    assembler.flush(onEpoch);
    r.framer = dec.framerStats();
    r.addresses = dec.addressStats();
    r.finalDialect = dec.dialect();
    return r;
}

} // namespace

void addAddressStats(std::vector<AddressStats> &into, const std::vector<AddressStats> &from) {
    std::unordered_map<std::string, std::size_t> index;
    for (std::size_t i = 0; i < into.size(); ++i) index.emplace(into[i].address, i);
    for (const auto &a : from) {
        auto it = index.find(a.address);
        if (it == index.end()) {
            it = index.emplace(a.address, into.size()).first;
            into.push_back(AddressStats{a.address});
        }
        AddressStats &t = into[it->second];
        auto add = [](std::uint64_t &x, std::uint64_t y) { x += y; };
        add(t.sentences, a.sentences);
        add(t.decoded, a.decoded);
        add(t.decodeErrors, a.decodeErrors);
        add(t.unknown, a.unknown);
        add(t.checksumBad, a.checksumBad);
        add(t.checksumMissing, a.checksumMissing);
        add(t.rejected, a.rejected);
    }
}

void addFramerStats(FramerStats &into, const FramerStats &f) {
    into.bytesIn += f.bytesIn;
    into.bytesSkipped += f.bytesSkipped;
    into.sentences += f.sentences;
    into.truncated += f.truncated;
    into.tooLong += f.tooLong;
    into.binaryAborted += f.binaryAborted;
}

namespace {

bool sameCounts(const SegmentRun &a, const SegmentRun &b) {
    if (a.epochs != b.epochs || a.hasFirst != b.hasFirst ||
        a.addresses.size() != b.addresses.size())
        return false;
    if (a.firstEpochTime.has_value() != b.firstEpochTime.has_value() ||
        (a.firstEpochTime && !(*a.firstEpochTime == *b.firstEpochTime)))
        return false;
    for (std::size_t i = 0; i < a.addresses.size(); ++i) {
        const AddressStats &x = a.addresses[i], &y = b.addresses[i];
        if (x.address != y.address || x.decoded != y.decoded || x.decodeErrors != y.decodeErrors ||
            x.unknown != y.unknown || x.rejected != y.rejected)
            return false;
    }
    return true;
}

} // namespace

std::size_t lineEndAfter(std::string_view log, std::size_t from) {
    for (std::size_t p = from; (p = log.find_first_of("\r\n", p)) != std::string_view::npos;) {
        if (log[p] == '\n') return p + 1;
        if (p + 1 == log.size()) return std::string_view::npos; // a CR whose LF may follow
        return log[p + 1] == '\n' ? p + 2 : p + 1;
    }
    return std::string_view::npos;
}

std::size_t lastLineEnd(std::string_view log) {
    std::size_t p = log.find_last_of("\r\n");
    if (p != std::string_view::npos && p + 1 == log.size() && log[p] == '\r')
        p = p == 0 ? std::string_view::npos : log.find_last_of("\r\n", p - 1);
    return p == std::string_view::npos ? 0 : p + 1;
}

// Segment boundaries: at the first line end after each equal share of the log.
std::vector<std::string_view> cutLog(std::string_view log, unsigned pieces) {
    if (pieces == 0) pieces = 1;
    std::vector<std::string_view> out;
    std::size_t start = 0;
    for (unsigned k = 1; k < pieces; ++k) {
        std::size_t target = log.size() / pieces * k;
        if (target <= start) continue;
        const std::size_t end = lineEndAfter(log, target);
        if (end == std::string_view::npos) break;
        out.push_back(log.substr(start, end - start));
        start = end;
    }
    out.push_back(log.substr(start));
    return out;
}

void runPieces(std::size_t count, unsigned threads, FunctionRef<void(std::size_t)> work) {
    std::atomic<std::size_t> next{0};
    auto loop = [&] {
        for (std::size_t k; (k = next.fetch_add(1)) < count;) work(k);
    };
    const std::size_t helpers = std::min<std::size_t>(count, std::max(1u, threads)) - (count > 0);
    std::vector<std::thread> workers;
    for (std::size_t i = 0; i < helpers; ++i) workers.emplace_back(loop);
    loop();
    for (auto &w : workers) w.join();
}

namespace {

// Read front to back, a segment would have started with `inForce` known (the caller's choice: one
// that began without it): its own run, corrected when that could have changed anything.
void correctSegment(SegmentRun &r, std::string_view seg, const DialectRegistry &registry,
                    const DecoderOptions &options, const Dialect *inForce) {
    if (r.detectLineStart == kNoDetection || r.finalDialect != inForce) {
        r = runSegment(seg, registry, options, inForce);
    } else if (r.detectLineStart > 0) {
        // Did knowing the dialect change anything before this segment named it? Usually not (it
        // matters for optional checksums and vendor readings of standard sentences); when it did,
        // decode the whole segment again as it was meant.
        const std::string_view prefix = seg.substr(0, r.detectLineStart);
        const SegmentRun asRun = runSegment(prefix, registry, options, nullptr);
        const SegmentRun asMeant = runSegment(prefix, registry, options, inForce);
        if (!sameCounts(asRun, asMeant)) r = runSegment(seg, registry, options, inForce);
    }
}

} // namespace

LogScanResult scanLog(std::string_view log, const DialectRegistry &registry,
                      const DecoderOptions &options, unsigned threads, std::size_t minSegmentBytes,
                      unsigned piecesPerThread) {
    if (threads == 0) threads = 1;
    const std::size_t bySize =
            std::max<std::size_t>(1, log.size() / std::max<std::size_t>(1, minSegmentBytes));
    // Several pieces per thread: a core slowed by something else takes fewer of them, instead of
    // the others waiting for it. One thread gains nothing from pieces.
    const std::size_t wanted =
            threads == 1 ? 1 : std::size_t{threads} * std::max(1u, piecesPerThread);
    const unsigned pieces = static_cast<unsigned>(std::min<std::size_t>(wanted, bySize));
    const std::vector<std::string_view> segs = cutLog(log, pieces);

    std::vector<SegmentRun> runs(segs.size());
    runPieces(segs.size(), threads,
              [&](std::size_t k) { runs[k] = runSegment(segs[k], registry, options, nullptr); });

    // The dialect in force at the start of each segment, read front to back: the first one named
    // stays (a decoder that knows its dialect never changes it), so it follows from the runs as
    // they are, and the corrections are independent of each other and run in parallel too.
    std::vector<std::size_t> toCorrect;
    std::vector<const Dialect *> inForceAt(segs.size(), nullptr);
    for (std::size_t k = 1; k < segs.size(); ++k) {
        inForceAt[k] = inForceAt[k - 1] ? inForceAt[k - 1] : runs[k - 1].finalDialect;
        if (inForceAt[k] && runs[k].initialDialect != inForceAt[k]) toCorrect.push_back(k);
    }
    runPieces(toCorrect.size(), threads, [&](std::size_t i) {
        const std::size_t k = toCorrect[i];
        correctSegment(runs[k], segs[k], registry, options, inForceAt[k]);
    });

    LogScanResult result;
    result.segments = static_cast<unsigned>(segs.size());
    result.threads = std::min(threads, result.segments);
    const Dialect *inForce = runs[0].finalDialect;
    addFramerStats(result.framer, runs[0].framer);
    addAddressStats(result.addresses, runs[0].addresses);
    result.epochs = runs[0].epochs;
    std::optional<TimeOfDay> lastTime = runs[0].lastEpochTime;
    bool haveLast = runs[0].hasFirst;

    for (std::size_t k = 1; k < segs.size(); ++k) {
        const SegmentRun &r = runs[k];
        addFramerStats(result.framer, r.framer);
        addAddressStats(result.addresses, r.addresses);
        result.epochs += r.epochs;
        // The epoch in progress at the cut was counted by both sides: when both sides give it
        // the same time, and when one side saw none of its time-carrying sentences (a segment
        // of GSV/GSA alone, or the sentences before the first time of the log: front to back,
        // they are part of the epoch around them).
        if (haveLast && r.hasFirst &&
            (!lastTime || !r.firstEpochTime || *lastTime == *r.firstEpochTime))
            --result.epochs;
        if (r.hasFirst) {
            // A segment without a time joined the epoch before it, which goes on.
            if (r.lastEpochTime) lastTime = r.lastEpochTime;
            haveLast = true;
        }
        if (!inForce) inForce = r.finalDialect;
    }
    result.dialect = inForce;
    rtcm::RtcmFramer frames;
    const auto count = [&](const rtcm::RtcmFrame &f) { ++result.rtcmTypes[f.messageNumber()]; };
    frames.feed(log, count);
    frames.finish(count);
    result.rtcm = frames.stats();
    return result;
}

} // namespace gnss
