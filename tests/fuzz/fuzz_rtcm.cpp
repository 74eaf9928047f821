// Fuzz harness: bytes → RtcmFramer → decodeMessage → JSON (what `gnss-cli rtcm` prints).
//
// Input: byte 0 picks a chunking, the rest is the correction stream. Checks that
// bytesIn == bytesInFrames + bytesSkipped after finish(), that frames add up to the per-type
// counts, that every frame's CRC is what the encoder computes for its payload, that every
// message's JSON is valid, that a decoded station, antenna, MSM header, bias or legacy
// observables message encodes back to the same values (in no more bytes: trailing bytes of a
// frame are not kept), and that the chunked run gives exactly the output of a one-shot run.
#include "fuzz_common.h"
#include "rtcm/rtcm_encoder.h"
#include "rtcm/rtcm_json.h"
#include "rtcm/rtcm_stream_decoder.h"

using namespace gnss;
using namespace gnss::rtcm;
using namespace gnss::fuzz;

namespace {

std::string json(const RtcmMessage &m) {
    std::string out;
    JsonWriter w(out);
    writeRtcmJson(w, m);
    return out;
}

std::string_view text(std::span<const std::uint8_t> b) {
    return {reinterpret_cast<const char *>(b.data()), b.size()};
}

// A message this library can encode decodes, once encoded, to the same JSON.
void checkReencodes(const RtcmMessage &m, const std::string &original) {
    std::string frameBytes;
    if (const auto *a = std::get_if<StationArp>(&m.body))
        frameBytes = encodeStationArp(*a);
    else if (const auto *i = std::get_if<AntennaInfo>(&m.body))
        frameBytes = encodeAntennaInfo(m.number, *i);
    else if (const auto *h = std::get_if<MsmHeader>(&m.body))
        frameBytes = encodeMsm(*h);
    else if (const auto *b = std::get_if<GlonassBiases>(&m.body))
        frameBytes = encodeGlonassBiases(*b);
    else if (const auto *o = std::get_if<LegacyObservables>(&m.body))
        frameBytes = encodeLegacy(*o);
    else
        return;
    check(frameBytes.size() >= kFrameOverhead, "a decoded message does not encode", original);
    const auto *p = reinterpret_cast<const std::uint8_t *>(frameBytes.data());
    const RtcmMessage again = decodeMessage({p + 3, frameBytes.size() - kFrameOverhead});
    // The encoder writes what the message holds and no more: a frame that carried bytes past
    // its content (an MSM whose masks name fewer cells than its length has room for) comes back
    // shorter, and otherwise the same.
    check(again.length <= m.length, "re-encoding made a message longer", original);
    RtcmMessage asLong = again;
    asLong.length = m.length;
    const std::string back = json(asLong);
    if (back != original)
        fail("decode → encode → decode changed a message", original + "\n  vs\n  " + back);
}

struct Run {
    std::vector<std::string> messages;
    std::string summary;
};

// `deep`: check JSON syntax and re-encoding too (one of two runs over the same bytes is enough).
Run run(std::string_view bytes, const std::vector<std::size_t> &sizes, bool deep) {
    RtcmStreamDecoder dec;
    RtcmFramer framer; // the same bytes through the framer alone: frames as bytes
    Run r;
    std::vector<std::string> frames;
    auto onFrame = [&](const RtcmFrame &f) {
        check(f.bytes.size() >= kFrameOverhead && f.bytes.size() <= kMaxFrame,
              "a frame of impossible size");
        check(frame(f.payload()) == text(f.bytes), "a frame's CRC is not the encoder's");
        frames.emplace_back(text(f.bytes));
    };
    auto onMessage = [&](const RtcmMessage &m) {
        std::string j = json(m);
        if (deep) checkJson(j, "an RTCM message's JSON is not valid JSON");
        const std::size_t k = r.messages.size();
        check(k < frames.size(), "a message without a frame", j);
        const std::string_view f = frames[k];
        check(m.length == f.size() - kFrameOverhead, "message length != payload size", j);
        if (f.size() >= 8)
            checkEqual<unsigned>(m.number,
                                 (unsigned(std::uint8_t(f[3])) << 4) | (std::uint8_t(f[4]) >> 4),
                                 "message number != the frame's DF002");
        if (deep && m.error.empty()) checkReencodes(m, j);
        r.messages.push_back(std::move(j));
    };
    std::size_t pos = 0;
    for (std::size_t n : sizes) {
        framer.feed(bytes.substr(pos, n), onFrame);
        dec.feed(bytes.substr(pos, n), onMessage);
        pos += n;
    }
    framer.finish(onFrame);
    dec.finish(onMessage);
    checkEqual<std::size_t>(r.messages.size(), frames.size(), "messages != frames");

    const RtcmFramerStats &s = dec.framerStats();
    checkEqual<std::uint64_t>(s.bytesIn, bytes.size(), "bytesIn != bytes fed");
    checkEqual<std::uint64_t>(s.bytesIn, s.bytesInFrames + s.bytesSkipped,
                              "bytesIn != bytesInFrames + bytesSkipped after finish()");
    check(s.truncated <= 1, "more than one truncation counted by one finish()");
    std::uint64_t perType = 0;
    for (const auto &[number, count] : dec.typeCounts()) perType += count;
    checkEqual<std::uint64_t>(perType, s.frames, "per-type counts != frames");
    checkEqual<std::uint64_t>(s.frames, frames.size(), "frames counted != frames emitted");
    JsonWriter w(r.summary);
    writeRtcmSummaryJson(w, dec);
    checkJson(r.summary, "the RTCM summary is not valid JSON");
    return r;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Input in(data, size);
    const std::uint8_t chunkSeed = in.byte();
    const std::string_view bytes = in.rest();

    const Run whole = run(bytes, {bytes.size()}, true);
    const Run chunked = run(bytes, chunking(chunkSeed, bytes.size()), false);
    check(whole.messages.size() == chunked.messages.size(), "chunking changed the message count");
    for (std::size_t i = 0; i < whole.messages.size(); ++i)
        if (whole.messages[i] != chunked.messages[i])
            fail("chunking changed a message",
                 whole.messages[i] + "\n  vs\n  " + chunked.messages[i]);
    if (whole.summary != chunked.summary)
        fail("chunking changed the counts", whole.summary + "\n  vs\n  " + chunked.summary);
    return 0;
}
