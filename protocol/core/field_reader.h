#pragma once
// FieldReader: typed access to a sentence's fields for decoders.
//
// Empty fields read as std::nullopt; a field that is present but malformed records an error
// (the first one wins) and also reads as std::nullopt, so a decoder reads every field straight
// through and checks ok() once at the end. Nothing throws.
#include "core/field_parse.h"
#include "core/refusal.h"
#include "core/sentence.h"

#include <optional>
#include <string>

namespace gnss {

class FieldReader {
public:
    explicit FieldReader(const Sentence &s) : s_(s) {}

    const Sentence &sentence() const { return s_; }
    std::size_t count() const { return s_.fieldCount(); }
    std::string_view text(std::size_t i) const { return s_.field(i); }
    bool empty(std::size_t i) const { return s_.field(i).empty(); }

    [[gnu::always_inline]] std::optional<double> real(std::size_t i, const char *name) {
        const auto t = s_.field(i);
        if (t.empty()) return std::nullopt;
        double v;
        if (parseReal(t, v)) return v;
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "not a number"));
        return std::nullopt;
    }
    [[gnu::always_inline]] std::optional<int> integer(std::size_t i, const char *name) {
        const auto t = s_.field(i);
        if (t.empty()) return std::nullopt;
        int v;
        if (parseSmallInt(t, v)) return v; // hot path: inline, no error bookkeeping
        return integerSlow(i, name);
    }
    // integer(), written straight into `out` (left as it is for an empty field). The hot
    // decoders read their fields so: an optional<int> returned by value is put together in
    // memory from its value and its flag and then read back whole, a store-forwarding stall on
    // every field (a fifth of a GSV decode).
    [[gnu::always_inline]] void integerInto(std::size_t i, const char *name,
                                            std::optional<int> &out) {
        int v;
        if (integerValue(i, name, v)) out = v;
    }
    // The same into a plain int: true when field i holds one (false when it is empty, or not an
    // integer: the error is recorded).
    [[gnu::always_inline]] bool integerValue(std::size_t i, const char *name, int &out) {
        switch (s_.smallField(i, out)) { // most integer fields: straight from the sentence
        case Sentence::kSmallNumber: return true;
        case Sentence::kEmpty: return false;
        case Sentence::kOther: break;
        }
        const auto t = s_.field(i);
        if (t.empty()) return false; // blanks only
        if (parseSmallInt(t, out)) return true;
        const auto slow = integerSlow(i, name);
        if (slow) out = *slow;
        return slow.has_value();
    }
    std::optional<std::int64_t> integer64(std::size_t i, const char *name);
    std::optional<std::uint64_t> hex(std::size_t i, const char *name);
    // A single character (status, mode, unit); a longer field is an error.
    std::optional<char> letter(std::size_t i, const char *name);
    // Field i holds ddmm.mmmm, field i+1 the hemisphere: signed decimal degrees.
    std::optional<double> latitude(std::size_t i, const char *name);
    std::optional<double> longitude(std::size_t i, const char *name);
    std::optional<TimeOfDay> time(std::size_t i, const char *name);
    std::optional<Date> date(std::size_t i, const char *name);
    std::optional<std::string_view> str(std::size_t i) const {
        auto t = s_.field(i);
        return t.empty() ? std::nullopt : std::optional<std::string_view>(t);
    }

    // Records an error unless the sentence has at least n fields after the address.
    bool require(std::size_t n);
    // Records an error for field i: `what` is a phrase marked QT_TRANSLATE_NOOP("Refusal", ...)
    // ("not a number"), shown translated in "field 3 (quality): not a number: 'x'".
    void fail(std::size_t i, const char *name, const char *what);
    // Records a sentence-level error: a refusal, or a plain sentence (a literal marked
    // QT_TRANSLATE_NOOP("Refusal", ...) is translated as it is).
    void failSentence(Refusal why);

    bool ok() const { return problem_.empty(); }
    const std::string &error() const { return problem_.text; }
    const Refusal &problem() const { return problem_; }

private:
    std::optional<int> integerSlow(std::size_t i, const char *name);
    std::optional<double> coordinate(std::size_t i, const char *name, int maxDeg, char pos,
                                     char neg);
    const Sentence &s_;
    Refusal problem_;
};

} // namespace gnss
