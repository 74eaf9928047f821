#pragma once
// What the GeoS-5 output encoders share (geostar_encoders.h): refusals in the words the decoders
// and the settings use, checks of text and hex fields, and the time and date fields.
#include "core/field_types.h"
#include "core/refusal.h"
#include "core/settings_schema.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace gnss::geostar::detail {

// "%1: %2 is out of range; accepted: %3".
Refusal outOfRange(std::string_view name, std::string value, std::string accepted);
// "%1: '%2' is not one of: %3".
Refusal notOneOf(std::string_view name, std::string value, std::string accepted);
// The decoders' own refusal of a field: "field %1 (%2): %3: '%4'" (`field` counted from 1 after
// the address, `what` one of their QT_TRANSLATE_NOOP phrases).
Refusal fieldRefusal(std::size_t field, std::string_view name, const char *what,
                     std::string_view value);

// Text printed as it is (a receiver name, a firmware version): at most `maxLength` printable
// characters, none that ends or splits a field. Empty refusal when it can be printed.
Refusal checkText(std::string_view name, std::string_view text, std::size_t maxLength);
bool isHex(std::string_view s);

// "hhmmss.ss" (the GeoS-5 prints hundredths), "" for no time; refused outside one day.
Refusal formatTime(const std::optional<TimeOfDay> &t, std::string &out);
// "ddmmyy", "" for no date; refused where the decoder would not read it back (years 1980-2079).
Refusal formatDate(const std::optional<Date> &d, std::string_view name, std::string &out);

// One sentence "$" + body + "*hh", or the refusal.
EncodeResult sentence(const std::string &body);
EncodeResult refused(Refusal why);

} // namespace gnss::geostar::detail
