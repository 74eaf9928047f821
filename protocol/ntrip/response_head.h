#pragma once
// ResponseHeadParser: what an NTRIP caster answered, read from the first bytes of its reply.
//
//   ICY 200 OK                                      NTRIP 1: data follows at once
//   SOURCETABLE 200 OK + headers + blank line       NTRIP 1: a source table follows
//   HTTP/1.1 200 OK + Content-Type: gnss/data       NTRIP 2: data (Transfer-Encoding: chunked?)
//   HTTP/1.1 200 OK + Content-Type: gnss/sourcetable
//   HTTP/1.x 401 Unauthorized, 404 Not Found, other codes
//   ERROR - Bad Password                            some NTRIP 1 casters
//
// Fed any chunking (one byte at a time or all at once), it reaches the same head and hands the
// same body bytes on: every decision is taken byte by byte on what has arrived. Nothing it is
// given can make it throw or grow without bound; a reply that is not an NTRIP/HTTP one is
// classified as such (NotNtrip) as soon as its first bytes rule the known status lines out.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gnss::ntrip {

enum class ReplyKind : std::uint8_t {
    Incomplete,        // not enough bytes yet
    Data,              // ICY 200 OK, or HTTP 200 with gnss/data (or no content type at all)
    SourceTable,       // SOURCETABLE 200 OK, or HTTP 200 with gnss/sourcetable
    Unauthorized,      // 401
    NotFound,          // 404
    OtherStatus,       // any other status code (statusCode says which)
    UnexpectedContent, // HTTP 200 with some other content type (a web server, not a caster)
    CasterError,       // an "ERROR - ..." line instead of a status line
    NotNtrip,          // not a status line any caster sends (binary, another protocol)
};

// Which status line the caster used: tells the NTRIP revision that answered.
enum class ReplyStyle : std::uint8_t {
    Unknown,
    Icy,         // "ICY 200 OK": NTRIP 1
    SourceTable, // "SOURCETABLE 200 OK": NTRIP 1
    Http,        // "HTTP/1.x ...": NTRIP 2 when Ntrip-Version says so, plain HTTP otherwise
    Error,       // "ERROR - ...": NTRIP 1
};

struct ResponseHead {
    ReplyKind kind = ReplyKind::Incomplete;
    ReplyStyle style = ReplyStyle::Unknown;
    int statusCode = 0;       // 200, 401 ... (0 for ERROR lines and when unknown)
    std::string statusLine;   // as received, without CR LF; non-printable bytes as '?'
    std::string httpVersion;  // "1.0", "1.1" (Http style only)
    std::string contentType;  // lower case, no parameters, control bytes '?': "gnss/data"
    std::string ntripVersion; // the Ntrip-Version header ("Ntrip/2.0"), empty when none
    bool chunked = false;     // Transfer-Encoding ends in "chunked"
    std::optional<std::uint64_t> contentLength;
    std::vector<std::pair<std::string, std::string>> headers; // as received (at most 64)
    std::uint32_t badHeaderLines = 0;                         // header lines without a colon

    // True for the NTRIP 1 styles (ICY, SOURCETABLE, ERROR lines).
    bool isNtrip1() const {
        return style == ReplyStyle::Icy || style == ReplyStyle::SourceTable ||
               style == ReplyStyle::Error;
    }
    // "NTRIP 1 (ICY)", "NTRIP 1 (SOURCETABLE)", "NTRIP 2 (HTTP/1.1)", "HTTP/1.0", "unknown".
    std::string revisionText() const;
};

class ResponseHeadParser {
public:
    static constexpr std::size_t kMaxLine = 1024;  // a longer line is not a reply head
    static constexpr std::size_t kMaxHead = 16384; // nor is a longer head
    static constexpr std::size_t kMaxHeaders = 64;

    // Feeds reply bytes; those after the head are appended to `body`.
    void feed(std::string_view bytes, std::string &body);
    // The connection closed: a head cut short is judged on what arrived (a status line alone is
    // enough: some casters close right after "HTTP/1.0 401 Unauthorized" without a blank line).
    void finish();

    // The status line has been read (kind may still be Incomplete for HTTP 200, which needs the
    // Content-Type header).
    bool statusKnown() const { return state_ != State::Status; }
    // The whole head has been read: every further byte is body.
    bool headComplete() const { return state_ == State::Body; }
    const ResponseHead &head() const { return head_; }

private:
    enum class State : std::uint8_t { Status, Headers, IcyHeaders, Body };
    void statusByte(char c);
    void headerByte(char c);
    void icyHeaderByte(char c, std::string &body);
    void parseStatusLine(std::string_view line);
    void parseHeaderLine(std::string_view line);
    void endOfHead();
    void notNtrip();

    State state_ = State::Status;
    ResponseHead head_;
    std::string line_;
    std::size_t headBytes_ = 0;
};

} // namespace gnss::ntrip
