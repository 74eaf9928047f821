#pragma once
// Credentials kept out of words. A caster's password goes into the Authorization header and
// nowhere else; these make sure no status line, error or host shown to the user carries it,
// whatever a caster answers (one that echoes the request back) or a user types (a host given
// as "user:password@caster").
#include <string>
#include <string_view>

namespace gnss::ntrip {

inline constexpr std::string_view kRedacted = "***";

// `text` with every occurrence of "user:password", of its Base64 form (the Authorization
// header's) and of the password itself replaced by "***". The password alone is masked only
// when it is at least kMinMaskedPassword characters long: a shorter one would mask ordinary
// letters of the message (and is no secret worth the name).
inline constexpr std::size_t kMinMaskedPassword = 4;
std::string redactCredentials(std::string_view text, std::string_view user,
                              std::string_view password);

// Whether a host as typed holds user information ("user[:password]@host"): such a text is
// refused, never echoed.
bool hasUserInfo(std::string_view host);

// A host as it may be shown: "user:password@caster" becomes "***@caster"; any other is itself.
std::string hostForDisplay(std::string_view host);

} // namespace gnss::ntrip
