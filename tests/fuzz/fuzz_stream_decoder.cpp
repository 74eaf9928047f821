// Fuzz harness: bytes → Framer → StreamDecoder, for every dialect choice.
//
// Input: byte 0 picks the decoder options (dialect, lenient, address alias) and whether the
// payload is repeated into a long stream (fuzz_nmea.h), byte 1 picks a chunking, the rest is the
// serial stream. Checks that the counts add up (fuzz_nmea.h), that every event's JSON is valid,
// and that the chunked run gives exactly the events and counts of a one-shot run over the same
// bytes.
#include "fuzz_nmea.h"

using namespace gnss;
using namespace gnss::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const StreamInput in(data, size);
    const Transcript whole = decodeInChunks(in.bytes, in.options, {in.bytes.size()}, true);
    checkCounts(whole, in.bytes.size(), in.options);
    const Transcript chunked =
            decodeInChunks(in.bytes, in.options, chunking(in.chunkSeed, in.bytes.size()), false);
    checkCounts(chunked, in.bytes.size(), in.options);
    checkSame(whole, chunked, "chunking changed the decoder's output");
    return 0;
}
