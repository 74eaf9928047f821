#include "geostar/geostar_encode_util.h"

#include "core/sentence_builder.h"
#include "nmea/nmea_encoders.h"

#include <cstdio>

namespace gnss::geostar::detail {

Refusal outOfRange(std::string_view name, std::string value, std::string accepted) {
    return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                   {std::string(name), std::move(value), std::move(accepted)});
}

Refusal notOneOf(std::string_view name, std::string value, std::string accepted) {
    return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: '%2' is not one of: %3"),
                   {std::string(name), std::move(value), std::move(accepted)});
}

Refusal fieldRefusal(std::size_t field, std::string_view name, const char *what,
                     std::string_view value) {
    return refusal(QT_TRANSLATE_NOOP("Refusal", "field %1 (%2): %3: '%4'"),
                   {std::to_string(field), std::string(name), what, std::string(value)});
}

Refusal checkText(std::string_view name, std::string_view text, std::size_t maxLength) {
    if (text.size() > maxLength)
        return refusal(
                QT_TRANSLATE_NOOP("Refusal", "%1: the value is %2 characters long; at most %3"),
                {std::string(name), std::to_string(text.size()), std::to_string(maxLength)});
    for (char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u >= 0x7F || c == ',' || c == '*' || c == '$' || c == '!' || c == '\\')
            return refusal(
                    QT_TRANSLATE_NOOP("Refusal", "%1: character not allowed in a value: '%2'"),
                    {std::string(name), std::string(1, c)});
    }
    return {};
}

bool isHex(std::string_view s) {
    for (char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f')))
            return false;
    return true;
}

Refusal formatTime(const std::optional<TimeOfDay> &t, std::string &out) {
    out.clear();
    if (!t) return {};
    if (t->nanos < 0 || t->nanos >= 86'400'000'000'000LL)
        return outOfRange("time", t->toString(2), "00:00:00.00..23:59:59.99");
    out = nmea::formatTime(*t, 2);
    return {};
}

Refusal formatDate(const std::optional<Date> &d, std::string_view name, std::string &out) {
    out.clear();
    if (!d) return {};
    if (d->day < 1 || d->day > 31 || d->month < 1 || d->month > 12 || d->year < 1980 ||
        d->year > 2079)
        return outOfRange(name, d->toString(), "1980-01-01..2079-12-31");
    out = nmea::formatDate(*d);
    return {};
}

EncodeResult sentence(const std::string &body) {
    EncodeResult r;
    r.sentences.push_back(buildSentence(body));
    return r;
}

EncodeResult refused(Refusal why) {
    EncodeResult r;
    r.refuse(std::move(why));
    return r;
}

} // namespace gnss::geostar::detail
