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

// A sentence a person typed, checked as NMEA 0183 asks before anything is sent: '$' (or '!')
// optional, an address of upper-case letters and digits, only printable characters outside the
// reserved ones ($ ! * \ ~), and a checksum that is either left out (it is added) or right.
// A wrong checksum is refused, naming the right one, unless `fixChecksum`: then it is replaced
// and `note` says so. Returns the sentence to send, or an empty string with `error` set.
std::string checkTypedSentence(std::string_view typed, bool fixChecksum, std::string &error,
                               std::string *note = nullptr);

// A proprietary prefix a user may configure: 'P' followed by 1 to 8 upper-case letters or
// digits. Returns an empty string when valid, else why not.
std::string checkAddressPrefix(std::string_view prefix);

// "$PNMRX110,0*hh" with from "PNMRX" and to "PXYZW" → "$PXYZW110,0*hh" (checksum recomputed).
// Sentences not starting with `from` are returned unchanged.
std::string renameAddressPrefix(std::string_view sentence, std::string_view from,
                                std::string_view to);

// Decimal formatting for encoders: fixed decimals, no locale, no exponent.
std::string formatFixed(double v, int decimals);

} // namespace gnss
