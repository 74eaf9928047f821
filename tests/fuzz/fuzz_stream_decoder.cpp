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
    Input in(data, size);
    const std::uint8_t control = in.byte();
    const DecoderOptions options = decoderOptions(control);
    const std::uint8_t chunkSeed = in.byte();
    std::string storage;
    const std::string_view bytes = streamOf(control, in.rest(), storage);

    const Transcript whole = decodeInChunks(bytes, options, {bytes.size()}, true);
    checkCounts(whole, bytes.size(), options);
    const Transcript chunked =
            decodeInChunks(bytes, options, chunking(chunkSeed, bytes.size()), false);
    checkCounts(chunked, bytes.size(), options);
    checkSame(whole, chunked, "chunking changed the decoder's output");
    return 0;
}
