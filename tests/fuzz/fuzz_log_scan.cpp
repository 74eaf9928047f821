// Fuzz harness: scanLog (a log decoded in segments on several threads, counts merged) against
// one StreamDecoder + EpochAssembler reading the same bytes front to back. Every count must be
// the same, as tests/tst_log_scan.cpp checks on generated logs.
//
// Input: byte 0 picks the decoder options (fuzz_nmea.h), byte 1 the thread count (1-4, low two
// bits) and the least segment size (1 << the next bits, 1 to 64 bytes: small, so that short
// inputs are cut too), the rest is the log.
#include "fuzz_nmea.h"
#include "log_scan_reference.h"

using namespace gnss;
using namespace gnss::fuzz;

namespace {

GNSS_FUZZ_NO_COVERAGE std::string describe(const LogScanResult &r) {
    std::string s =
            "segments " + std::to_string(r.segments) + ", epochs " + std::to_string(r.epochs) +
            ", dialect " + std::string(r.dialect ? r.dialect->id : "none") + ", framer " +
            std::to_string(r.framer.bytesIn) + "/" + std::to_string(r.framer.bytesSkipped) + "/" +
            std::to_string(r.framer.sentences) + "/" + std::to_string(r.framer.truncated) + "/" +
            std::to_string(r.framer.tooLong) + "/" + std::to_string(r.framer.binaryAborted);
    for (const AddressStats &a : r.addresses)
        s += "\n    " + a.address + " " + std::to_string(a.sentences) + " " +
             std::to_string(a.decoded) + " " + std::to_string(a.decodeErrors) + " " +
             std::to_string(a.unknown) + " " + std::to_string(a.checksumBad) + " " +
             std::to_string(a.checksumMissing) + " " + std::to_string(a.rejected);
    return s;
}

GNSS_FUZZ_NO_COVERAGE bool same(const LogScanResult &a, const LogScanResult &b) {
    const FramerStats &x = a.framer, &y = b.framer;
    if (x.bytesIn != y.bytesIn || x.bytesSkipped != y.bytesSkipped || x.sentences != y.sentences ||
        x.truncated != y.truncated || x.tooLong != y.tooLong ||
        x.binaryAborted != y.binaryAborted || a.epochs != b.epochs || a.dialect != b.dialect ||
        a.addresses.size() != b.addresses.size())
        return false;
    for (std::size_t i = 0; i < a.addresses.size(); ++i) {
        const AddressStats &p = a.addresses[i], &q = b.addresses[i];
        if (p.address != q.address || p.sentences != q.sentences || p.decoded != q.decoded ||
            p.decodeErrors != q.decodeErrors || p.unknown != q.unknown ||
            p.checksumBad != q.checksumBad || p.checksumMissing != q.checksumMissing ||
            p.rejected != q.rejected)
            return false;
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Input in(data, size);
    const std::uint8_t control = in.byte();
    const DecoderOptions options = decoderOptions(control);
    const std::uint8_t split = in.byte();
    const unsigned threads = 1 + (split & 3);
    const std::size_t minSegment = std::size_t{1} << ((split >> 2) % 7);
    const unsigned piecesPerThread = 1 + ((split >> 5) & 3);
    std::string storage;
    const std::string_view log = streamOf(control, in.rest(), storage);

    const LogScanResult seq = gnss::test::scanFrontToBack(log, registry(), options);
    const LogScanResult par =
            scanLog(log, registry(), options, threads, minSegment, piecesPerThread);
    check(par.segments >= 1 && par.segments <= (threads == 1 ? 1 : threads * piecesPerThread),
          "scanLog cut more segments than asked");
    if (!same(seq, par))
        fail("scanLog counts differ from one front-to-back pass",
             "front to back: " + describe(seq) + "\n  scanLog: " + describe(par));
    return 0;
}
