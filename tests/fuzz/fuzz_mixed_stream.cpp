// Fuzz harness: one byte stream carrying NMEA and RTCM 3 interleaved → StreamDecoder (its Framer
// and its RtcmFramer side by side, what a base that talks NMEA and sends corrections on one port
// gives).
//
// Input: byte 0 picks a chunking, the rest is the stream. Checks that every frame handed over is
// whole (its length field, CRC-24Q right), that the frames' bytes add up to the framer's count
// and the per-type counts to the frames, that junk is what neither framer took (never more than
// the sentence framer skipped), that every line handed over is sentence text, and that the
// chunked run gives exactly the sentences, frames and counts of a one-shot run.
#include "fuzz_nmea.h"
#include "rtcm/crc24q.h"

using namespace gnss;
using namespace gnss::fuzz;

namespace {

struct MixedRun {
    std::vector<std::string> lines, frames;
    std::uint64_t junk = 0, skipped = 0, frameBytes = 0, typeTotal = 0, frameCount = 0;
};

MixedRun decodeMixed(std::string_view bytes, const std::vector<std::size_t> &sizes) {
    StreamDecoder dec(registry());
    MixedRun r;
    dec.setFrameHandler([&](const rtcm::RtcmFrame &f) {
        const auto b = f.bytes;
        check(b.size() >= rtcm::kFrameOverhead && b[0] == rtcm::kPreamble,
              "a frame handed over has no header");
        const std::size_t length = (std::size_t(b[1] & 0x03) << 8) | b[2];
        check(length + rtcm::kFrameOverhead == b.size(), "a frame's length field is not its size");
        const std::uint32_t crc = rtcm::crc24q(b.data(), b.size() - 3);
        const std::uint32_t stored =
                (std::uint32_t(b[b.size() - 3]) << 16) | (b[b.size() - 2] << 8) | b[b.size() - 1];
        check(crc == stored, "a frame handed over has a wrong CRC");
        r.frames.emplace_back(reinterpret_cast<const char *>(b.data()), b.size());
    });
    std::size_t at = 0;
    for (std::size_t n : sizes) {
        n = std::min(n, bytes.size() - at);
        dec.feed(bytes.substr(at, n), [&](const SentenceEvent &ev) {
            checkLine(ev.sentence.line());
            r.lines.emplace_back(ev.sentence.line());
        });
        at += n;
    }
    dec.finish();
    check(at == bytes.size(), "the chunking did not cover the input");
    r.junk = dec.junkBytes();
    r.skipped = dec.framerStats().bytesSkipped;
    r.frameBytes = dec.rtcmStats().bytesInFrames;
    r.frameCount = dec.rtcmStats().frames;
    for (const auto &[type, n] : dec.rtcmTypes()) r.typeTotal += n;
    return r;
}

void checkMixed(const MixedRun &r, std::size_t inputSize) {
    std::uint64_t sum = 0;
    for (const auto &f : r.frames) sum += f.size();
    checkEqual<std::uint64_t>(sum, r.frameBytes, "frame sizes != bytesInFrames");
    checkEqual<std::uint64_t>(r.frames.size(), r.frameCount, "frames handed over != frames");
    checkEqual<std::uint64_t>(r.typeTotal, r.frameCount, "per-type counts != frames");
    check(r.junk <= r.skipped, "junk is more than the sentence framer skipped");
    check(r.frameBytes <= inputSize, "more frame bytes than input");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 1) return 0;
    const std::string_view bytes(reinterpret_cast<const char *>(data + 1), size - 1);
    const MixedRun whole = decodeMixed(bytes, {bytes.size()});
    checkMixed(whole, bytes.size());
    const MixedRun chunked = decodeMixed(bytes, chunking(data[0], bytes.size()));
    checkMixed(chunked, bytes.size());
    check(whole.lines == chunked.lines, "chunking changed the sentences");
    check(whole.frames == chunked.frames, "chunking changed the frames");
    checkEqual<std::uint64_t>(whole.junk, chunked.junk, "chunking changed the junk");
    return 0;
}
