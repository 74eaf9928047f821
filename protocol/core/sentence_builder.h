#pragma once
// Building outgoing sentences: every encoder ends here, so every sentence we send carries a
// correct checksum.
#include <string>
#include <string_view>

namespace gnss {

// "$" + body + "*" + two upper-case hex digits (no line terminator).
std::string buildSentence(std::string_view body, char start = '$');

// Accepts what a user typed ("PNVGVER", "$PNVGVER", "$PNVGVER*4E", "$PNVGVER*00") and returns the
// sentence with a correct checksum, or an empty string with `error` set when it cannot be a
// sentence (empty, non-printable characters, too long).
std::string completeSentence(std::string_view typed, std::string &error);

// Decimal formatting for encoders: fixed decimals, no locale, no exponent.
std::string formatFixed(double v, int decimals);

} // namespace gnss
