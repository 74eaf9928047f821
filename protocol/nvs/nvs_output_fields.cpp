#include "nvs/nvs_output_fields.h"

#include "core/sentence_builder.h"
#include "nmea/nmea_encoders.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnss::nvs {

namespace {

std::string number(double v) {
    return formatFixed(v, v == std::floor(v) ? 0 : 6);
}

bool framing(char c) {
    const auto u = static_cast<unsigned char>(c);
    return c == ',' || c == '*' || c == '$' || c == '!' || c == '\\' || u < 0x20 || u >= 0x7F;
}

} // namespace

Refusal outOfRange(std::string name, std::string value, std::string accepted) {
    return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                   {std::move(name), std::move(value), std::move(accepted)});
}

OutputFields::OutputFields(std::string_view address) : address_(address), body_(address) {}

std::string OutputFields::name(std::string_view field) const {
    return std::string(address_) + " " + std::string(field);
}

void OutputFields::refuse(Refusal why) {
    if (why_.empty()) why_ = std::move(why);
}

OutputFields &OutputFields::time(std::string_view field, const std::optional<TimeOfDay> &t) {
    body_ += ',';
    if (!t || !ok()) return *this;
    // A leap second (23:59:60) is a time of day too.
    constexpr std::int64_t kDay = 86'401'000'000'000LL;
    if (t->nanos < 0 || t->nanos >= kDay || t->decimals > 9) {
        refuse(outOfRange(name(field), t->toString(), "00:00:00..23:59:60.999999999"));
        return *this;
    }
    if (t->nanos < 86'400'000'000'000LL) {
        body_ += nmea::formatTime(*t, t->decimals);
        return *this;
    }
    // 23:59:60.s-s: rounded at its decimals, never into the next day.
    std::int64_t unit = 1'000'000'000, digits = 1;
    for (int i = 0; i < t->decimals; ++i) unit /= 10, digits *= 10;
    const std::int64_t frac =
            std::min<std::int64_t>((t->nanos - 86'400'000'000'000LL + unit / 2) / unit, digits - 1);
    char buf[32];
    if (t->decimals > 0)
        std::snprintf(buf, sizeof buf, "235960.%0*lld", int(t->decimals),
                      static_cast<long long>(frac));
    else
        std::snprintf(buf, sizeof buf, "235960");
    body_ += buf;
    return *this;
}

OutputFields &OutputFields::real(std::string_view field, std::optional<double> v, int decimals,
                                 double min, double max) {
    body_ += ',';
    if (!v || !ok()) return *this;
    if (!std::isfinite(*v)) {
        refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: expected a number, got '%2'"),
                       {name(field), std::isnan(*v) ? "nan" : (*v > 0 ? "inf" : "-inf")}));
        return *this;
    }
    if (*v < min || *v > max) {
        refuse(outOfRange(name(field), number(*v), number(min) + ".." + number(max)));
        return *this;
    }
    body_ += formatFixed(*v, decimals);
    return *this;
}

OutputFields &OutputFields::integer(std::string_view field, std::optional<std::int64_t> v,
                                    std::int64_t min, std::int64_t max, int width) {
    body_ += ',';
    if (!v || !ok()) return *this;
    if (*v < min || *v > max) {
        refuse(outOfRange(name(field), std::to_string(*v),
                          std::to_string(min) + ".." + std::to_string(max)));
        return *this;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%0*lld", width, static_cast<long long>(*v));
    body_ += buf;
    return *this;
}

OutputFields &OutputFields::mode(std::string_view field, std::optional<char> m) {
    body_ += ',';
    if (!m || !ok()) return *this;
    if (*m == '\0' || kModeIndicators.find(*m) == std::string_view::npos) {
        const auto u = static_cast<unsigned char>(*m);
        refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: '%2' is not one of: %3"),
                       {name(field), u >= 0x20 && u < 0x7F ? std::string(1, *m) : "?",
                        "A, D, F, R, E, N"}));
        return *this;
    }
    body_ += *m;
    return *this;
}

OutputFields &OutputFields::text(std::string_view field, std::optional<std::string_view> v) {
    body_ += ',';
    if (!v || !ok()) return *this;
    for (char c : *v) {
        if (!framing(c)) continue;
        const auto u = static_cast<unsigned char>(c);
        refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: character not allowed in a value: '%2'"),
                       {name(field), u >= 0x20 && u < 0x7F ? std::string(1, c) : "?"}));
        return *this;
    }
    body_ += *v;
    return *this;
}

OutputFields &OutputFields::fields(std::string_view checked) {
    body_ += ',';
    body_ += checked;
    return *this;
}

EncodeResult OutputFields::build() const {
    EncodeResult r;
    if (!ok())
        r.refuse(why_);
    else
        r.sentences.push_back(buildSentence(body_));
    return r;
}

} // namespace gnss::nvs
