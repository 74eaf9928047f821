#pragma once
// The requests an NTRIP client sends: a stream from a mountpoint, or the source table.
//
//   NTRIP 1:  GET /MOUNT HTTP/1.0            NTRIP 2:  GET /MOUNT HTTP/1.1
//             User-Agent: NTRIP ...                    Host: caster:2101
//             Authorization: Basic ...                 Ntrip-Version: Ntrip/2.0
//                                                      User-Agent: NTRIP ...
//                                                      Authorization: Basic ...
//                                                      Connection: close
//
// An empty mountpoint asks for the source table (GET /). Authorization is sent only when a
// user name is given. Every field is checked before it goes into the request, so nothing a user
// typed can add header lines.
#include <cstdint>
#include <string>
#include <string_view>

namespace gnss::ntrip {

enum class NtripVersion : std::uint8_t { V1 = 1, V2 = 2 };

inline constexpr std::string_view kUserAgent = "NTRIP GNSSWorkbench/0.1";

struct RequestTarget {
    std::string host; // for NTRIP 2's Host header
    std::uint16_t port = 2101;
    std::string mountpoint; // without the leading '/'; empty: the source table
    NtripVersion version = NtripVersion::V2;
    std::string user; // empty: no Authorization header
    std::string password;
};

// The request bytes, or an empty string with `error` set when a field cannot be sent.
std::string buildRequest(const RequestTarget &target, std::string &error);

// Why this mountpoint name cannot be requested (empty when it can): control characters,
// spaces, '?', '#' or a leading '/'.
std::string checkMountpoint(std::string_view mountpoint);

// "Basic " + Base64(user:password).
std::string basicAuthorization(std::string_view user, std::string_view password);

} // namespace gnss::ntrip
