#pragma once
// Base64 (RFC 4648, standard alphabet, '=' padding) for HTTP Basic authentication. Written here
// so the NTRIP library needs nothing but the standard library.
#include <optional>
#include <string>
#include <string_view>

namespace gnss::ntrip {

std::string base64Encode(std::string_view bytes);
// None when `text` is not padded Base64 (length not a multiple of 4, a foreign character,
// padding in the middle). The test casters use it to read the Authorization header.
std::optional<std::string> base64Decode(std::string_view text);

} // namespace gnss::ntrip
