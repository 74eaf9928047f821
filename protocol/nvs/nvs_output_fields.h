#pragma once
// OutputFields: the body of a sentence the receiver sends, built field by field for the NVS
// output encoders (the mirror of FieldReader). Each field is checked as it is added: a number
// must be finite and within what its field holds (a value a receiver never prints is refused
// rather than printed as "nan" or as 300 digits), a mode indicator one of the spec's letters,
// text free of the characters that frame a sentence. The first refusal wins; nothing is built.
#include "core/field_table.h"
#include "core/field_types.h"
#include "core/refusal.h"
#include "core/settings_schema.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gnss::nvs {

class OutputFields {
public:
    // `address` starts the body ("PNVGBRS") and names the fields in refusals ("PNVGBRS course").
    explicit OutputFields(std::string_view address);

    // hhmmss.s-s with the decimals the time carries (TimeOfDay::decimals, as decoded); an empty
    // field when nullopt.
    OutputFields &time(std::string_view name, const std::optional<TimeOfDay> &t);
    // Fixed decimals (the receiver's own layout of the field), within [min, max].
    OutputFields &real(std::string_view name, std::optional<double> v, int decimals, double min,
                       double max);
    // Zero-padded to `width` digits when given ("0043"), within [min, max].
    OutputFields &integer(std::string_view name, std::optional<std::int64_t> v, std::int64_t min,
                          std::int64_t max, int width = 0);
    // Mode indicator of chapter 4: A autonomous, D differential, F float RTK, R RTK, E estimated,
    // N not valid.
    OutputFields &mode(std::string_view name, std::optional<char> m);
    // Text as it is (a name, a version): no ',', '*', '$', '!', '\', control or non-ASCII.
    OutputFields &text(std::string_view name, std::optional<std::string_view> v);
    // Fields another encoder built and checked ("ddmm.mmmm,N,..."), appended after a comma.
    OutputFields &fields(std::string_view checked);
    // Each row's field of `m` (core/field_table.h): a time, a real with the row's decimals and
    // range, a count within the row's range, a mode indicator, text.
    template <class M, class Rows> OutputFields &rows(const M &m, const Rows &table) {
        for (const auto &row : table)
            std::visit([&](auto p) { add(row.name, m.*p, row.layout); }, row.member);
        return *this;
    }

    void refuse(Refusal why);
    bool ok() const { return why_.empty(); }
    // The sentence ("$" body "*hh"), or the first refusal.
    EncodeResult build() const;

private:
    void add(std::string_view n, const std::optional<TimeOfDay> &t, const FieldLayout &) {
        time(n, t);
    }
    void add(std::string_view n, std::optional<double> v, const FieldLayout &l) {
        real(n, v, l.decimals, l.min, l.max);
    }
    void add(std::string_view n, std::optional<std::int64_t> v, const FieldLayout &l) {
        integer(n, v, static_cast<std::int64_t>(l.min), static_cast<std::int64_t>(l.max));
    }
    void add(std::string_view n, std::optional<int> v, const FieldLayout &l) {
        add(n, v ? std::optional<std::int64_t>(*v) : std::nullopt, l);
    }
    void add(std::string_view n, std::optional<char> m, const FieldLayout &) { mode(n, m); }
    void add(std::string_view n, std::optional<std::string_view> v, const FieldLayout &) {
        text(n, v);
    }
    std::string name(std::string_view field) const;
    std::string_view address_;
    std::string body_;
    Refusal why_;
};

// The mode letters of chapter 4, in the spec's order.
inline constexpr std::string_view kModeIndicators = "ADFREN";

// Bounds of what a field can hold where the spec gives none: far beyond any value a receiver
// reports, near enough to keep a field to a few characters.
inline constexpr double kMaxMetres = 1e8;            // distances, base-lines, deviations
inline constexpr double kMaxSpeed = 1e5;             // m/s
inline constexpr double kMaxAcceleration = 1e3;      // m/s^2
inline constexpr double kMaxDop = 1e3;               // dilutions of precision
inline constexpr std::int64_t kMaxCount = 1LL << 53; // counters (exact in a double, as JSON)

// The sentence of a message that is just its rows (as OutputFields::rows).
template <class M, class Rows> EncodeResult encodeRows(const M &m, const Rows &rows) {
    OutputFields f(m.type->name);
    f.rows(m, rows);
    return f.build();
}

// "<name>: <value> is out of range; accepted: <accepted>" (the schema's template).
Refusal outOfRange(std::string name, std::string value, std::string accepted);

} // namespace gnss::nvs
