#pragma once
// CasterRequestParser: what an NTRIP client sends a caster, read incrementally (the caster's half
// of the protocol; the client's is ntrip_request.h).
//
//   NTRIP 1:  GET /MOUNT HTTP/1.0             NTRIP 2:  GET /MOUNT HTTP/1.1
//             User-Agent: NTRIP ...                     Host: caster:2101
//             Authorization: Basic ...                  Ntrip-Version: Ntrip/2.0
//             (Ntrip-GGA: $GPGGA,...)                   Authorization: Basic ...
//             CR LF                                     CR LF
//
// Bytes in, in any chunking: NeedMore until the empty line that ends the head, then Complete
// (the bytes after it, a GGA an NTRIP 1 rover sends at once, are kept in rest()) or Malformed
// with a reason and the HTTP status to answer (400; 405 for a method other than GET). A head
// longer than kMaxHead or a line longer than kMaxLine is malformed: the parser never holds more.
// The path "/" (or nothing after it) asks for the source table. Lines may end in CR LF or LF.
// Plain C++, never throws.
#include "ntrip/ntrip_request.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace gnss::ntrip {

struct CasterRequest {
    std::string method;                      // "GET"
    std::string target;                      // as sent: "/MOUNT", "/"
    std::string mountpoint;                  // without '/' and query; empty: the source table
    std::string httpVersion;                 // "HTTP/1.0" or "HTTP/1.1"
    NtripVersion version = NtripVersion::V1; // V2 when Ntrip-Version says Ntrip/2.x
    bool hasAuthorization = false;           // an Authorization header was sent
    std::string authScheme;                  // "Basic", "Digest" ... as sent
    std::string user, password;              // decoded from Basic
    std::string userAgent, host, ntripGga;
    std::size_t headers = 0; // header lines read

    bool wantsSourceTable() const { return mountpoint.empty(); }
};

class CasterRequestParser {
public:
    enum class State : std::uint8_t { NeedMore, Complete, Malformed };
    static constexpr std::size_t kMaxHead = 8192;
    static constexpr std::size_t kMaxLine = 2048;
    static constexpr std::size_t kMaxHeaders = 64;
    static constexpr std::size_t kMaxRest = 4096; // bytes kept after the head

    // Reads `bytes`; once Complete or Malformed, more bytes change nothing (after Complete they
    // are appended to rest(), up to kMaxRest).
    State feed(std::string_view bytes);

    State state() const { return state_; }
    const CasterRequest &request() const { return request_; }
    // When Malformed: why (printable ASCII) and the status to answer: 400 or 405.
    const std::string &reason() const { return reason_; }
    int statusCode() const { return status_; }
    // Bytes of the head read so far (all of it once Complete).
    std::size_t headBytes() const { return headBytes_; }
    const std::string &rest() const { return rest_; }

private:
    void line(std::string_view l);
    void requestLine(std::string_view l);
    void header(std::string_view name, std::string_view value);
    void fail(std::string why, int status = 400);

    State state_ = State::NeedMore;
    CasterRequest request_;
    std::string line_;
    bool sawRequestLine_ = false;
    std::size_t headBytes_ = 0;
    std::string reason_;
    int status_ = 0;
    std::string rest_;
};

// The whole head at once (for tests and the fuzzer).
CasterRequestParser parseCasterRequest(std::string_view bytes);

} // namespace gnss::ntrip
