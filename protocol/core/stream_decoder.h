#pragma once
// StreamDecoder: bytes in, decoded sentences out, everything counted.
//
//   bytes → Framer → Sentence::parse → checksum policy → DialectRegistry::lookup → decode
//        ↘ RtcmFramer → RTCM 3 frames (CRC-24Q right), counted per message type
//
// One stream may interleave NMEA and RTCM 3 (a base that talks to the host and sends its
// corrections on the same port): both framers see every byte. The bytes of RTCM frames are not
// junk (junkBytes()); the frames go to a frame handler when one is set.
// Never throws and never stops: every line ends up either decoded or reported with the reason
// (unknown address, checksum bad or missing, malformed field), and counted per address.
#include "core/dialect_registry.h"
#include "core/framer.h"
#include "core/function_ref.h"
#include "rtcm/rtcm_framer.h"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace gnss {

struct DecoderOptions {
    // "auto" (recognised from the stream's proprietary sentences) or a dialect id.
    std::string dialect = "auto";
    // Decode sentences whose checksum is bad or missing, and mark them.
    bool lenient = false;
    // Renamed address prefixes: {"PXYZW", "PNMRX"} reads $PXYZW110 as $PNMRX110.
    std::vector<std::pair<std::string, std::string>> addressAliases;
    // Look for RTCM 3 frames beside the sentences (off where a caller frames the bytes whole
    // itself: the multi-threaded log scan, whose segments would each frame them again).
    bool frameRtcm = true;
};

struct AddressStats {
    std::string address;
    std::uint64_t sentences = 0;       // lines with this address
    std::uint64_t decoded = 0;         // decoded into a message
    std::uint64_t decodeErrors = 0;    // known sentence, malformed content
    std::uint64_t unknown = 0;         // no decoder for this address
    std::uint64_t checksumBad = 0;     // checksum present and wrong
    std::uint64_t checksumMissing = 0; // no checksum
    std::uint64_t rejected = 0;        // not decoded because of the checksum policy
};

struct SentenceEvent {
    const Sentence &sentence;
    const Message *message = nullptr; // decoded value, or nullptr
    std::string_view error;           // why not decoded (empty when decoded)
    const Dialect *dialect = nullptr; // dialect of the rule that matched (nullptr: standard)
    bool unknown = false;             // no decoder for this address (not an error on a line)
    // `error` as a translatable refusal, when it was made from one; otherwise `error` is a
    // phrase marked QT_TRANSLATE_NOOP("Refusal", ...) or plain text.
    const Refusal *problem = nullptr;
};

// The JSON object `gnss-cli decode` prints for one sentence: line, address, talker, type,
// checksum, and data (the decoded values) or error (why not).
void writeSentenceEventJson(JsonWriter &w, const SentenceEvent &ev);

class StreamDecoder {
public:
    using Handler = FunctionRef<void(const SentenceEvent &)>;

    StreamDecoder(const DialectRegistry &registry, DecoderOptions options = {});

    // Feeds raw bytes from the receiver.
    void feed(std::string_view bytes, const Handler &handler);
    // End of stream (counts a dangling partial sentence).
    void finish();
    // Forgets a partial sentence without counting it (a baud switch: what came before is noise).
    void resetFraming() {
        framer_.reset();
        rtcm_.reset();
    }
    // Decodes one already-framed line (no terminator).
    void decodeLine(std::string_view line, const Handler &handler);

    const FramerStats &framerStats() const { return framer_.stats(); }
    // RTCM 3 frames found in the same bytes, and how many of each message type.
    const rtcm::RtcmFramerStats &rtcmStats() const { return rtcm_.stats(); }
    const std::map<unsigned, std::uint64_t> &rtcmTypes() const { return rtcmTypes_; }
    // Bytes that are neither in a sentence nor in an RTCM frame.
    std::uint64_t junkBytes() const {
        const std::uint64_t skipped = framer_.stats().bytesSkipped;
        const std::uint64_t frames = rtcm_.stats().bytesInFrames;
        return skipped > frames ? skipped - frames : 0;
    }
    // Called with each RTCM frame as it is found (none: they are only counted).
    void setFrameHandler(std::function<void(const rtcm::RtcmFrame &)> handler) {
        frameHandler_ = std::move(handler);
    }
    // Per-address counters, in order of first appearance.
    const std::vector<AddressStats> &addressStats() const { return stats_; }
    std::uint64_t malformed() const { return malformed_; } // lines that are not sentences

    // The dialect in force: chosen, or detected (auto); nullptr while none is known.
    const Dialect *dialect() const { return dialect_; }
    const DialectRegistry &registry() const { return registry_; }
    const DecoderOptions &options() const { return options_; }
    // Forces a dialect (e.g. after active detection); nullptr returns to auto detection.
    void setDialect(const Dialect *d);

private:
    struct CacheEntry {
        std::uint64_t key = 0; // 0: free
        DialectRegistry::Match match;
        std::uint32_t statsIndex = 0;
    };
    struct Resolved {
        DialectRegistry::Match match;
        std::uint32_t statsIndex;
    };
    void onFrame(const rtcm::RtcmFrame &f);
    Resolved resolve(std::string_view address);
    void forgetAddresses(); // what resolve() learnt (the dialect changed)
    Resolved resolveSlow(std::string_view address);
    std::uint32_t statsIndexFor(std::string_view address);
    bool checksumAcceptable(const Sentence &s, const Dialect *ruleDialect) const;

    const DialectRegistry &registry_;
    DecoderOptions options_;
    Framer framer_;
    rtcm::RtcmFramer rtcm_;
    std::map<unsigned, std::uint64_t> rtcmTypes_;
    std::function<void(const rtcm::RtcmFrame &)> frameHandler_;
    const Dialect *dialect_ = nullptr;
    bool autoDetect_ = true;
    std::vector<AddressStats> stats_;
    std::unordered_map<std::string, std::uint32_t> statsByAddress_;
    std::array<CacheEntry, 256> cache_{};
    std::size_t cacheUsed_ = 0;
    CacheEntry last_; // the last address found in the cache
    std::uint64_t malformed_ = 0;
    std::string aliasBuffer_;
    Refusal problem_; // of the last checksum refusal (the event points at it)
};

} // namespace gnss
