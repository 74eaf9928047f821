// Fuzz harness: the NTRIP client's protocol half (protocol/ntrip) on what a caster may send.
//
// Input: byte 0 picks the mode (bits 0-1) and bit 2 repeats the payload until it is longer than
// a reply head may be (ResponseHeadParser::kMaxHead), so that short inputs reach the limits;
// byte 1 seeds the chunking the bytes arrive in (fuzz_common.h: byte at a time included),
// byte 2 seeds the rest (chunk sizes of an encoding, a rover position). The rest is the payload.
//
//   mode 0, 3: a whole reply, as NtripSource and SourceTableRequest read it: the head
//              (ResponseHeadParser), the body through the chunked decoder when the head says
//              chunked, and through the source table parser when it is a table. Fed in chunks
//              and at once, everything must be the same: head, body, data, table, errors.
//   mode 1:    the payload as a chunked body (ChunkedDecoder), in chunks and at once; and the
//              payload encoded in chunks (sizes, hex case, extensions, trailers, bare LFs from
//              byte 2) must decode to exactly the payload.
//   mode 2:    the payload as a source table, in chunks and at once; every line is accounted
//              for (a record, a bad line, a long line, blank or the end); the nearest mountpoint
//              to a position is one of the table's.
// Everywhere: the head's texts are printable ASCII, its kind agrees with its status code, the
// body is what follows the head in the reply, byte for byte; nothing grows past its limit.
#include "fuzz_common.h"
#include "ntrip/chunked_decoder.h"
#include "ntrip/mountpoint_distance.h"
#include "ntrip/response_head.h"
#include "ntrip/source_table.h"

#include <cmath>

using namespace gnss;
using namespace gnss::fuzz;
using namespace gnss::ntrip;

namespace {

GNSS_FUZZ_NO_COVERAGE bool printable(std::string_view s) {
    for (char c : s)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
            return false;
    return true;
}

// ---- the reply head -------------------------------------------------------------------------

GNSS_FUZZ_NO_COVERAGE bool same(const ResponseHead &a, const ResponseHead &b) {
    return a.kind == b.kind && a.style == b.style && a.statusCode == b.statusCode &&
           a.statusLine == b.statusLine && a.httpVersion == b.httpVersion &&
           a.contentType == b.contentType && a.ntripVersion == b.ntripVersion &&
           a.chunked == b.chunked && a.contentLength == b.contentLength && a.headers == b.headers &&
           a.badHeaderLines == b.badHeaderLines;
}

GNSS_FUZZ_NO_COVERAGE std::string describe(const ResponseHead &h) {
    std::string s = "kind " + std::to_string(int(h.kind)) + ", style " +
                    std::to_string(int(h.style)) + ", code " + std::to_string(h.statusCode) +
                    ", status '" + h.statusLine + "', type '" + h.contentType + "', chunked " +
                    std::to_string(h.chunked) + ", headers " + std::to_string(h.headers.size());
    return s;
}

GNSS_FUZZ_NO_COVERAGE void checkHead(const ResponseHead &h, std::string_view reply) {
    const std::string d = describe(h);
    check(printable(h.statusLine) && h.statusLine.size() <= 200,
          "the status line kept is not printable or too long", d);
    check(printable(h.httpVersion), "the HTTP version is not printable", d);
    check(printable(h.contentType), "the content type is not printable", d);
    check(printable(h.ntripVersion) && h.ntripVersion.size() <= 64,
          "the Ntrip-Version is not printable or too long", d);
    check(h.headers.size() <= ResponseHeadParser::kMaxHeaders, "more headers kept than allowed");
    for (const auto &[name, value] : h.headers)
        check(printable(name) && printable(value) && name.size() <= ResponseHeadParser::kMaxLine &&
                      value.size() <= ResponseHeadParser::kMaxLine,
              "a header kept is not printable or too long", name + ": " + value);
    for (char c : h.contentType)
        check(!(c >= 'A' && c <= 'Z') && c != ';',
              "the content type is not lower case without "
              "parameters",
              h.contentType);
    check(!reply.empty() == (h.kind != ReplyKind::Incomplete),
          "a reply read to its end is still incomplete (or nothing is not)", d);
    switch (h.kind) {
    case ReplyKind::Data:
    case ReplyKind::SourceTable:
    case ReplyKind::UnexpectedContent:
        check(h.statusCode == 200, "a reply taken as data or a table is no 200", d);
        break;
    case ReplyKind::Unauthorized: check(h.statusCode == 401, "401 kind without 401", d); break;
    case ReplyKind::NotFound: check(h.statusCode == 404, "404 kind without 404", d); break;
    case ReplyKind::OtherStatus:
        check(h.statusCode > 0 && h.statusCode <= 999 && h.statusCode != 200 &&
                      h.statusCode != 401 && h.statusCode != 404,
              "another status with a known or no code", d);
        break;
    case ReplyKind::CasterError:
        check(h.style == ReplyStyle::Error && h.statusCode == 0, "an ERROR line with a code", d);
        break;
    case ReplyKind::Incomplete:
    case ReplyKind::NotNtrip: break;
    }
    if (h.kind == ReplyKind::UnexpectedContent)
        check(!h.contentType.empty() && h.contentType != "gnss/data" &&
                      h.contentType != "gnss/sourcetable",
              "a caster's content type taken as unexpected", d);
    check(!h.chunked || h.style == ReplyStyle::Http || h.style == ReplyStyle::SourceTable ||
                  h.style == ReplyStyle::Icy,
          "chunked without headers", d);
}

// What a client makes of a reply: the head, then the body through the chunked decoder when the
// head says so and through the source table parser when it is a table (as SourceTableRequest
// takes a table: also under text/plain), or kept as data (as NtripSource passes it on).
struct ReplyRun {
    ResponseHead head;
    bool statusKnown = false, headComplete = false;
    std::string body;    // every body byte the head parser handed on
    std::string decoded; // the body after the chunked decoder (or as is)
    ChunkedDecoder::Status chunkStatus = ChunkedDecoder::Status::Ok;
    std::string chunkError;
    std::uint64_t chunks = 0, afterEnd = 0;
    bool isTable = false;
    SourceTable table;
};

ReplyRun readReply(std::string_view reply, const std::vector<std::size_t> &sizes) {
    ResponseHeadParser parser;
    ChunkedDecoder chunks;
    SourceTableParser table;
    ReplyRun r;
    bool decided = false;
    auto takeBody = [&](std::string_view body) {
        if (body.empty()) return;
        r.body.append(body);
        const ResponseHead &h = parser.head();
        if (!decided) {
            decided = true;
            r.isTable = h.kind == ReplyKind::SourceTable ||
                        (h.kind == ReplyKind::UnexpectedContent && h.contentType == "text/plain");
        }
        std::string out;
        if (h.chunked) {
            const std::size_t before = out.size();
            chunks.feed(body, out);
            check(out.size() - before <= body.size(), "the chunked decoder made bytes up");
        } else {
            out.assign(body);
        }
        r.decoded.append(out);
        if (r.isTable) table.feed(out);
    };
    std::size_t pos = 0;
    for (std::size_t n : sizes) {
        const std::string_view piece = reply.substr(pos, n);
        pos += n;
        // Every byte through the parser: after the head it hands them on as body (or drops
        // them, after a reply that is no NTRIP one; a client has closed the connection then).
        const bool knownBefore = parser.statusKnown();
        std::string body;
        parser.feed(piece, body);
        check(!knownBefore || parser.statusKnown(), "a known status became unknown");
        check(body.empty() || parser.headComplete(), "body bytes handed on before the head's end");
        takeBody(body);
    }
    r.statusKnown = parser.statusKnown();
    r.headComplete = parser.headComplete();
    parser.finish();
    table.finish();
    r.head = parser.head();
    r.chunkStatus = chunks.status();
    r.chunkError = chunks.error();
    r.chunks = chunks.chunks();
    r.afterEnd = chunks.bytesAfterEnd();
    r.table = table.take();
    return r;
}

// ---- source tables --------------------------------------------------------------------------

GNSS_FUZZ_NO_COVERAGE bool same(const StreamEntry &a, const StreamEntry &b) {
    return a.mountpoint == b.mountpoint && a.identifier == b.identifier && a.format == b.format &&
           a.formatDetails == b.formatDetails && a.carrier == b.carrier &&
           a.navSystem == b.navSystem && a.network == b.network && a.country == b.country &&
           a.latitude == b.latitude && a.longitude == b.longitude && a.wantsGga == b.wantsGga &&
           a.solution == b.solution && a.generator == b.generator &&
           a.compression == b.compression && a.authentication == b.authentication &&
           a.fee == b.fee && a.bitrate == b.bitrate && a.misc == b.misc;
}

GNSS_FUZZ_NO_COVERAGE bool same(const CasterEntry &a, const CasterEntry &b) {
    return a.host == b.host && a.port == b.port && a.identifier == b.identifier &&
           a.casterOperator == b.casterOperator && a.nmea == b.nmea && a.country == b.country &&
           a.latitude == b.latitude && a.longitude == b.longitude &&
           a.fallbackHost == b.fallbackHost && a.fallbackPort == b.fallbackPort && a.misc == b.misc;
}

GNSS_FUZZ_NO_COVERAGE bool same(const NetworkEntry &a, const NetworkEntry &b) {
    return a.identifier == b.identifier && a.networkOperator == b.networkOperator &&
           a.authentication == b.authentication && a.fee == b.fee && a.webNet == b.webNet &&
           a.webStr == b.webStr && a.webReg == b.webReg && a.misc == b.misc;
}

template <class T>
GNSS_FUZZ_NO_COVERAGE bool sameList(const std::vector<T> &a, const std::vector<T> &b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i])) return false;
    return true;
}

GNSS_FUZZ_NO_COVERAGE bool same(const SourceTable &a, const SourceTable &b) {
    return sameList(a.streams, b.streams) && sameList(a.casters, b.casters) &&
           sameList(a.networks, b.networks) && a.complete == b.complete &&
           a.shortRecords == b.shortRecords && a.badLines == b.badLines &&
           a.longLines == b.longLines;
}

GNSS_FUZZ_NO_COVERAGE std::string describe(const SourceTable &t) {
    return std::to_string(t.streams.size()) + " STR, " + std::to_string(t.casters.size()) +
           " CAS, " + std::to_string(t.networks.size()) + " NET, complete " +
           std::to_string(t.complete) + ", short " + std::to_string(t.shortRecords) + ", bad " +
           std::to_string(t.badLines) + ", long " + std::to_string(t.longLines);
}

GNSS_FUZZ_NO_COVERAGE std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

GNSS_FUZZ_NO_COVERAGE void checkPosition(const std::optional<double> &lat,
                                         const std::optional<double> &lon) {
    check(!lat || (std::isfinite(*lat) && std::fabs(*lat) <= 90), "a latitude off the Earth");
    check(!lon || (std::isfinite(*lon) && *lon >= -180 && *lon <= 180),
          "a longitude out of -180..180");
}

// The table of `text`: every line accounted for, every value in its range.
GNSS_FUZZ_NO_COVERAGE void checkTable(const SourceTable &t, std::string_view text) {
    std::uint64_t records = 0, ends = 0, longLines = 0;
    while (!text.empty()) {
        const std::size_t nl = text.find('\n');
        const std::string_view line = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        if (line.size() > SourceTableParser::kMaxLine)
            ++longLines;
        else if (trimmed(line) == "ENDSOURCETABLE")
            ++ends;
        else if (!trimmed(line).empty())
            ++records;
    }
    const std::string d = describe(t);
    check(t.complete == (ends > 0), "ENDSOURCETABLE seen or not, but the table says otherwise", d);
    checkEqual<std::uint64_t>(t.longLines, longLines, "long source table lines miscounted");
    checkEqual<std::uint64_t>(t.streams.size() + t.casters.size() + t.networks.size() + t.badLines,
                              records, "source table lines not accounted for");
    check(t.streams.size() + t.casters.size() + t.networks.size() <= SourceTableParser::kMaxRecords,
          "more records kept than allowed", d);
    check(t.shortRecords <= t.streams.size() + t.casters.size() + t.networks.size(),
          "more short records than records", d);
    for (const StreamEntry &s : t.streams) {
        check(!s.mountpoint.empty(), "a stream without a mountpoint", d);
        checkPosition(s.latitude, s.longitude);
        check(t.find(s.mountpoint) != nullptr && t.find(s.mountpoint)->mountpoint == s.mountpoint,
              "find() misses a mountpoint of the table", s.mountpoint);
        (void)isRtcm3Format(s.format);
    }
    for (const CasterEntry &c : t.casters) {
        check(!c.host.empty(), "a caster without a host", d);
        checkPosition(c.latitude, c.longitude);
    }
    for (const NetworkEntry &n : t.networks)
        check(!n.identifier.empty(),
              "a network without a "
              "name",
              d);
}

void checkNearest(const SourceTable &t, Rng &rng) {
    const double lat = static_cast<double>(rng.below(18001)) / 100 - 90;
    const double lon = static_cast<double>(rng.below(36001)) / 100 - 180;
    NearestOptions o;
    o.rtcm3Only = (rng.next() & 1) != 0;
    o.onlyWantingGga = (rng.next() & 1) != 0;
    const NearestChoice c = nearestMountpoint(t, lat, lon, o);
    if (!c.entry) return;
    check(c.entry >= t.streams.data() && c.entry < t.streams.data() + t.streams.size(),
          "the nearest mountpoint is not one of the table's");
    check(std::isfinite(c.distanceMetres) && c.distanceMetres >= 0 &&
                  c.distanceMetres <= 3.1416 * kMeanEarthRadius,
          "a distance over half the Earth's circumference");
    check(entryPosition(*c.entry).has_value(), "the nearest mountpoint has no position");
}

SourceTable tableInChunks(std::string_view text, const std::vector<std::size_t> &sizes) {
    SourceTableParser p;
    std::size_t pos = 0;
    for (std::size_t n : sizes) {
        p.feed(text.substr(pos, n));
        pos += n;
    }
    p.finish();
    return p.take();
}

// ---- chunked bodies -------------------------------------------------------------------------

struct Chunked {
    std::string out;
    ChunkedDecoder::Status status = ChunkedDecoder::Status::Ok;
    std::string error;
    std::uint64_t chunks = 0, decoded = 0, afterEnd = 0;
};

Chunked decodeChunked(std::string_view in, const std::vector<std::size_t> &sizes) {
    ChunkedDecoder d;
    Chunked r;
    std::size_t pos = 0;
    for (std::size_t n : sizes) {
        const ChunkedDecoder::Status before = d.status();
        const std::size_t had = r.out.size();
        r.status = d.feed(in.substr(pos, n), r.out);
        check(r.status == d.status(), "feed() returned another status than status()");
        if (before != ChunkedDecoder::Status::Ok) {
            check(r.status == before, "the chunked decoder left its end or its error");
            check(r.out.size() == had, "the chunked decoder decoded after its end or error");
        }
        pos += n;
    }
    r.status = d.status();
    r.error = d.error();
    r.chunks = d.chunks();
    r.decoded = d.bytesDecoded();
    r.afterEnd = d.bytesAfterEnd();
    return r;
}

GNSS_FUZZ_NO_COVERAGE void checkSame(const Chunked &a, const Chunked &b, const char *what) {
    check(a.out == b.out && a.status == b.status && a.error == b.error && a.chunks == b.chunks &&
                  a.decoded == b.decoded && a.afterEnd == b.afterEnd,
          what,
          "status " + std::to_string(int(a.status)) + "/" + std::to_string(int(b.status)) +
                  ", bytes " + std::to_string(a.out.size()) + "/" + std::to_string(b.out.size()) +
                  ", errors '" + a.error + "' / '" + b.error + "'");
}

GNSS_FUZZ_NO_COVERAGE void checkChunked(const Chunked &r, std::size_t inSize) {
    checkEqual<std::uint64_t>(r.decoded, r.out.size(), "bytesDecoded() != bytes handed out");
    check(r.out.size() <= inSize, "the chunked decoder made bytes up");
    check((r.status == ChunkedDecoder::Status::Error) == !r.error.empty(),
          "an error without a reason, or a reason without an error", r.error);
    check(r.afterEnd == 0 || r.status == ChunkedDecoder::Status::Finished,
          "bytes after the end counted before the end");
}

// `payload` as a chunked body: sizes, hex case, extensions, line ends and trailers from `rng`.
std::string encodeChunked(std::string_view payload, Rng &rng, std::uint64_t &chunks,
                          std::size_t &extra) {
    const std::size_t largest = std::size_t{1} << rng.below(12);
    const bool upper = rng.next() & 1, bareLf = rng.below(4) == 0, ext = rng.below(4) == 0;
    const char *eol = bareLf ? "\n" : "\r\n";
    std::string out;
    chunks = 0;
    for (std::size_t pos = 0; pos < payload.size();) {
        const std::size_t n = std::min(payload.size() - pos, 1 + rng.below(largest));
        char head[24];
        std::snprintf(head, sizeof head, upper ? "%zX" : "%zx", n);
        if (rng.below(8) == 0) out += "00"; // leading zeros
        out += head;
        if (ext) out += ";name=value";
        out += eol;
        out.append(payload.substr(pos, n));
        out += eol;
        pos += n;
        ++chunks;
    }
    out += "0";
    out += eol;
    if (rng.below(4) == 0) out += std::string("X-Trailer: 1") + eol;
    out += eol;
    const std::string after = rng.below(4) == 0 ? "after the end" : "";
    extra = after.size();
    return out + after;
}

void checkChunkedMode(std::string_view payload, std::uint8_t feedSeed, Rng &rng) {
    const Chunked whole = decodeChunked(payload, {payload.size()});
    checkChunked(whole, payload.size());
    const Chunked pieces = decodeChunked(payload, chunking(feedSeed, payload.size()));
    checkSame(whole, pieces, "chunking changed what the chunked decoder decoded");

    // The payload sent chunked comes back exactly.
    std::uint64_t chunks = 0;
    std::size_t extra = 0;
    const std::string encoded = encodeChunked(payload, rng, chunks, extra);
    const Chunked back = decodeChunked(encoded, chunking(feedSeed, encoded.size()));
    check(back.status == ChunkedDecoder::Status::Finished,
          "a well-formed chunked body did not finish", back.error);
    check(back.out == payload, "a chunked body did not decode to what was sent");
    checkEqual<std::uint64_t>(back.chunks, chunks, "chunks miscounted");
    checkEqual<std::uint64_t>(back.afterEnd, extra, "bytes after the last chunk miscounted");
}

// ---- the whole reply ------------------------------------------------------------------------

void checkReplyMode(std::string_view reply, std::uint8_t feedSeed) {
    const ReplyRun whole = readReply(reply, {reply.size()});
    const ReplyRun pieces = readReply(reply, chunking(feedSeed, reply.size()));
    const std::string d = describe(whole.head);
    checkHead(whole.head, reply);
    check(same(whole.head, pieces.head), "chunking changed the reply head",
          d + "\n  vs\n  " + describe(pieces.head));
    check(whole.statusKnown == pieces.statusKnown && whole.headComplete == pieces.headComplete,
          "chunking changed when the head was known");
    check(whole.body == pieces.body, "chunking changed the body handed on");
    check(whole.decoded == pieces.decoded && whole.chunkStatus == pieces.chunkStatus &&
                  whole.chunkError == pieces.chunkError && whole.chunks == pieces.chunks &&
                  whole.afterEnd == pieces.afterEnd,
          "chunking changed the decoded body", whole.chunkError + " / " + pieces.chunkError);
    check(whole.isTable == pieces.isTable && same(whole.table, pieces.table),
          "chunking changed the source table",
          describe(whole.table) + " vs " + describe(pieces.table));

    // The body is what follows the head, exactly; a reply that is no NTRIP one hands none on.
    check(whole.body.size() <= reply.size() &&
                  reply.substr(reply.size() - whole.body.size()) == whole.body,
          "the body is not the end of the reply", d);
    if (whole.head.kind == ReplyKind::NotNtrip)
        check(whole.body.empty(), "a reply that is no NTRIP reply handed body bytes on", d);
    if (whole.head.kind == ReplyKind::Incomplete)
        check(!whole.headComplete, "a complete head of no kind", d);
    if (!whole.head.chunked) check(whole.decoded == whole.body, "an unchunked body was changed");
    if (whole.isTable) checkTable(whole.table, whole.decoded);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Input in(data, size);
    const std::uint8_t control = in.byte();
    const std::uint8_t feedSeed = in.byte();
    Rng rng(in.byte());
    std::string_view payload = in.rest();
    std::string storage;
    if ((control & 4) && !payload.empty()) {
        while (storage.size() <= ResponseHeadParser::kMaxHead + 64) storage.append(payload);
        payload = storage;
    }
    switch (control & 3) {
    case 1: checkChunkedMode(payload, feedSeed, rng); break;
    case 2: {
        const SourceTable whole = parseSourceTable(payload);
        checkTable(whole, payload);
        const SourceTable pieces = tableInChunks(payload, chunking(feedSeed, payload.size()));
        check(same(whole, pieces), "chunking changed the source table",
              describe(whole) + " vs " + describe(pieces));
        checkNearest(whole, rng);
        break;
    }
    default: checkReplyMode(payload, feedSeed); break;
    }
    return 0;
}
