#pragma once
// The NMEA side of the harnesses: decoder options from a control byte, and a StreamDecoder run
// recorded as a transcript (every event as `gnss-cli decode` prints it, and every count) that
// can be checked for its invariants and compared with another run of the same bytes.
#include "builtin/dialects.h"
#include "core/stream_decoder.h"
#include "fuzz_common.h"

#include <string>
#include <string_view>
#include <vector>

namespace gnss::fuzz {

inline const DialectRegistry &registry() {
    static const DialectRegistry r = makeBuiltinRegistry();
    return r;
}

// Control byte → decoder options: bits 0-2 the dialect (auto, nvs, geostar, nemerix, nmea;
// 5-7 wrap to auto, nvs, geostar), bit 3 lenient, bit 4 an address alias (PXYZW read as PNMRX,
// a renamed Nemerix prefix). Bit 5: see streamOf.
inline DecoderOptions decoderOptions(std::uint8_t b) {
    static constexpr const char *kIds[] = {"auto", "nvs", "geostar", "nemerix", "nmea"};
    DecoderOptions o;
    o.dialect = kIds[(b & 7) % 5];
    o.lenient = (b & 8) != 0;
    if (b & 16) o.addressAliases = {{"PXYZW", "PNMRX"}};
    return o;
}

// The stream the harness decodes: the payload, or with bit 5 of the control byte set, the
// payload repeated until it is longer than a line may be (Framer::kMaxLine), so that short
// inputs (the fuzzers run with -max_len=1024: faster) reach over-long lines and long logs too.
inline std::string_view streamOf(std::uint8_t b, std::string_view payload, std::string &storage) {
    if (!(b & 32) || payload.empty()) return payload;
    while (storage.size() <= Framer::kMaxLine + 64) storage.append(payload);
    return storage;
}

// The input of a harness that decodes one stream two ways: byte 0 the decoder options (and
// streamOf's repeat), byte 1 the seed of a chunking (fuzz_common.h), the rest the stream.
class StreamInput {
public:
    StreamInput(const std::uint8_t *data, std::size_t size) {
        Input in(data, size);
        const std::uint8_t control = in.byte();
        options = decoderOptions(control);
        chunkSeed = in.byte();
        bytes = streamOf(control, in.rest(), storage_);
    }
    StreamInput(const StreamInput &) = delete; // `bytes` may point into the storage
    StreamInput &operator=(const StreamInput &) = delete;

    DecoderOptions options;
    std::uint8_t chunkSeed = 0;
    std::string_view bytes;

private:
    std::string storage_;
};

struct Transcript {
    std::vector<std::string> events; // one JSON object per event
    std::uint64_t lineBytes = 0;     // bytes of the lines handed over (terminators excluded)
    std::uint64_t messages = 0;      // events that carry a message
    FramerStats framer;
    std::vector<AddressStats> addresses;
    std::uint64_t malformed = 0;
    const Dialect *dialect = nullptr;
};

// A framed line is '$' or '!' and sentence text, at most kMaxLine bytes.
GNSS_FUZZ_NO_COVERAGE inline void checkLine(std::string_view line) {
    check(!line.empty() && (line.front() == '$' || line.front() == '!'),
          "a line handed over does not start with '$' or '!'", line);
    check(line.size() <= Framer::kMaxLine, "a line longer than kMaxLine was handed over", line);
    for (char c : line)
        check(c == '\t' || (c >= 0x20 && c < 0x7F), "a line holds a byte no sentence contains",
              line);
}

// Records one event; `validate`: check its line and JSON too (one of two runs over the same
// bytes is enough: the other must give the very same text).
inline void record(Transcript &t, const SentenceEvent &ev, bool validate) {
    std::string json;
    JsonWriter w(json);
    writeSentenceEventJson(w, ev);
    const std::string_view line = ev.sentence.line();
    if (validate) {
        checkJson(json, "an event's JSON is not valid JSON");
        checkLine(line);
    }
    check((ev.message != nullptr) == ev.error.empty(),
          "an event has both a message and an error, or neither", json);
    t.lineBytes += line.size();
    if (ev.message) ++t.messages;
    t.events.push_back(std::move(json));
}

inline void finishTranscript(Transcript &t, StreamDecoder &dec) {
    dec.finish();
    t.framer = dec.framerStats();
    t.addresses = dec.addressStats();
    t.malformed = dec.malformed();
    t.dialect = dec.dialect();
}

// `bytes` fed in the given chunk sizes (they add up to its size).
inline Transcript decodeInChunks(std::string_view bytes, const DecoderOptions &options,
                                 const std::vector<std::size_t> &sizes, bool validate) {
    StreamDecoder dec(registry(), options);
    Transcript t;
    std::size_t pos = 0;
    for (std::size_t n : sizes) {
        dec.feed(bytes.substr(pos, n), [&](const SentenceEvent &ev) { record(t, ev, validate); });
        pos += n;
    }
    finishTranscript(t, dec);
    return t;
}

// The counts of one run add up.
GNSS_FUZZ_NO_COVERAGE inline void checkCounts(const Transcript &t, std::size_t inputSize,
                                              const DecoderOptions &o) {
    const FramerStats &f = t.framer;
    checkEqual<std::uint64_t>(f.bytesIn, inputSize, "framer bytesIn != bytes fed");
    checkEqual<std::uint64_t>(t.events.size(), f.sentences, "events != framed sentences");
    // Every byte is skipped, in a line handed over, or a line's terminator (one byte, or two
    // for CR LF); a dropped over-long line's terminator is not counted as skipped either.
    check(f.bytesSkipped + t.lineBytes <= f.bytesIn, "skipped + line bytes > bytes in");
    const std::uint64_t terminators = f.bytesIn - f.bytesSkipped - t.lineBytes;
    check(terminators >= f.sentences && terminators <= 2 * (f.sentences + f.tooLong),
          "bytes in != skipped + lines + terminators",
          std::to_string(terminators) + " terminator bytes for " + std::to_string(f.sentences) +
                  " sentences and " + std::to_string(f.tooLong) + " over-long lines");
    std::uint64_t sentences = 0, decoded = 0, malformedErrors = 0;
    for (const AddressStats &a : t.addresses) {
        sentences += a.sentences;
        decoded += a.decoded;
        check(a.sentences == a.decoded + a.decodeErrors + a.unknown + a.rejected,
              "an address's sentences != decoded + errors + unknown + rejected", a.address);
        check(a.checksumBad + a.checksumMissing <= a.sentences,
              "an address has more checksum faults than sentences", a.address);
        if (a.address == "(malformed)") malformedErrors += a.decodeErrors;
    }
    checkEqual<std::uint64_t>(sentences, f.sentences, "sum of per-address sentences != framed");
    checkEqual<std::uint64_t>(decoded, t.messages, "sum of decoded != events with a message");
    checkEqual<std::uint64_t>(malformedErrors, t.malformed, "(malformed) errors != malformed()");
    if (o.dialect != "auto")
        check(t.dialect == registry().find(o.dialect), "a chosen dialect did not stay in force");
}

// Two runs over the same bytes gave the same events and counts.
GNSS_FUZZ_NO_COVERAGE inline void checkSame(const Transcript &a, const Transcript &b,
                                            const char *what) {
    if (a.events.size() != b.events.size())
        fail(what, "event counts " + std::to_string(a.events.size()) + " and " +
                           std::to_string(b.events.size()));
    for (std::size_t i = 0; i < a.events.size(); ++i)
        if (a.events[i] != b.events[i]) fail(what, a.events[i] + "\n  vs\n  " + b.events[i]);
    const FramerStats &x = a.framer, &y = b.framer;
    check(x.bytesIn == y.bytesIn && x.bytesSkipped == y.bytesSkipped &&
                  x.sentences == y.sentences && x.truncated == y.truncated &&
                  x.tooLong == y.tooLong && x.binaryAborted == y.binaryAborted,
          what, "framer counts differ");
    check(a.addresses.size() == b.addresses.size(), what, "address lists differ in length");
    for (std::size_t i = 0; i < a.addresses.size(); ++i) {
        const AddressStats &p = a.addresses[i], &q = b.addresses[i];
        check(p.address == q.address && p.sentences == q.sentences && p.decoded == q.decoded &&
                      p.decodeErrors == q.decodeErrors && p.unknown == q.unknown &&
                      p.checksumBad == q.checksumBad && p.checksumMissing == q.checksumMissing &&
                      p.rejected == q.rejected,
              what, "counts of address " + p.address + " differ");
    }
    check(a.malformed == b.malformed, what, "malformed counts differ");
    check(a.dialect == b.dialect, what, "the dialect in force differs");
}

} // namespace gnss::fuzz
