// Fuzz harness: the caster's request parser (protocol/ntrip/caster_request.h) on whatever a
// client may send.
//
// Input: byte 0 seeds the chunking the bytes arrive in (fuzz_common.h: byte at a time
// included); the rest is what the client sends. Fed in chunks and at once, the result must be
// the same: state, request fields, reason, status, the bytes kept after the head. Everywhere:
// the parser never reads more than kMaxHead bytes into a head, a malformed head has a printable
// reason and answers 400 or 405, a complete one a mountpoint a request could name.
#include "fuzz_common.h"
#include "ntrip/caster_request.h"

using namespace gnss::fuzz;
using namespace gnss::ntrip;

namespace {

GNSS_FUZZ_NO_COVERAGE bool sameRequest(const CasterRequestParser &a, const CasterRequestParser &b) {
    const CasterRequest &x = a.request(), &y = b.request();
    return a.state() == b.state() && a.reason() == b.reason() && a.statusCode() == b.statusCode() &&
           a.rest() == b.rest() && a.headBytes() == b.headBytes() && x.method == y.method &&
           x.target == y.target && x.mountpoint == y.mountpoint && x.httpVersion == y.httpVersion &&
           x.version == y.version && x.hasAuthorization == y.hasAuthorization &&
           x.authScheme == y.authScheme && x.user == y.user && x.password == y.password &&
           x.userAgent == y.userAgent && x.host == y.host && x.ntripGga == y.ntripGga &&
           x.headers == y.headers;
}

GNSS_FUZZ_NO_COVERAGE bool printableReason(std::string_view s) {
    for (char c : s)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
            return false;
    return !s.empty();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Input in(data, size);
    const std::uint8_t feedSeed = in.byte();
    const std::string_view bytes = in.rest();

    CasterRequestParser whole;
    whole.feed(bytes);
    CasterRequestParser pieces;
    std::size_t pos = 0;
    for (std::size_t n : chunking(feedSeed, bytes.size())) {
        const auto before = pieces.state();
        const auto after = pieces.feed(bytes.substr(pos, n));
        check(before == CasterRequestParser::State::NeedMore || after == before,
              "a finished parser changed its state");
        pos += n;
    }
    check(sameRequest(whole, pieces), "chunking changed the request read", whole.reason());

    check(whole.headBytes() <= CasterRequestParser::kMaxHead + 1, "a head past the cap was read");
    check(whole.rest().size() <= CasterRequestParser::kMaxRest,
          "more kept after the head than allowed");
    switch (whole.state()) {
    case CasterRequestParser::State::Malformed:
        check(printableReason(whole.reason()), "a malformed head without a printable reason",
              whole.reason());
        check(whole.statusCode() == 400 || whole.statusCode() == 405,
              "a malformed head answered with neither 400 nor 405");
        break;
    case CasterRequestParser::State::Complete:
        check(whole.request().method == "GET", "a complete request that is no GET");
        check(checkMountpoint(whole.request().mountpoint).empty(),
              "a mountpoint no request could name", whole.request().mountpoint);
        check(whole.reason().empty() && whole.statusCode() == 0, "a complete head with a reason");
        break;
    case CasterRequestParser::State::NeedMore:
        check(whole.headBytes() == bytes.size(), "bytes left unread while more are needed");
        break;
    }
    return 0;
}
