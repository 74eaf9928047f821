#include "core/field_reader.h"

#include <climits>

namespace gnss {

namespace {

// Field i read by `parse`: nullopt when empty; when `parse` refuses it, `what` is recorded
// (a phrase marked QT_TRANSLATE_NOOP("Refusal", ...)) and it reads as nullopt too.
template <class T>
std::optional<T> parsed(FieldReader &r, std::size_t i, const char *name,
                        bool (*parse)(std::string_view, T &), const char *what) {
    const auto t = r.text(i);
    if (t.empty()) return std::nullopt;
    T v;
    if (parse(t, v)) return v;
    r.fail(i, name, what);
    return std::nullopt;
}

bool parseLetter(std::string_view s, char &out) {
    if (s.size() != 1) return false;
    out = s.front();
    return true;
}

} // namespace

void FieldReader::fail(std::size_t i, const char *name, const char *what) {
    if (!problem_.empty()) return;
    problem_ = refusal(QT_TRANSLATE_NOOP("Refusal", "field %1 (%2): %3: '%4'"),
                       {std::to_string(i + 1), name, what, std::string(s_.field(i))});
}

void FieldReader::failSentence(Refusal why) {
    if (problem_.empty()) problem_ = std::move(why);
}

bool FieldReader::require(std::size_t n) {
    if (s_.fieldCount() >= n) return true;
    failSentence(refusal(QT_TRANSLATE_NOOP("Refusal", "expected at least %1 fields, got %2"),
                         {std::to_string(n), std::to_string(s_.fieldCount())}));
    return false;
}

std::optional<std::int64_t> FieldReader::integer64(std::size_t i, const char *name) {
    return parsed(*this, i, name, parseInt, QT_TRANSLATE_NOOP("Refusal", "not an integer"));
}

std::optional<int> FieldReader::integerSlow(std::size_t i, const char *name) {
    auto v = integer64(i, name);
    if (!v) return std::nullopt;
    if (*v < INT_MIN || *v > INT_MAX) {
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "out of range"));
        return std::nullopt;
    }
    return static_cast<int>(*v);
}

std::optional<std::uint64_t> FieldReader::hex(std::size_t i, const char *name) {
    return parsed(*this, i, name, parseHex, QT_TRANSLATE_NOOP("Refusal", "not hexadecimal"));
}

std::optional<char> FieldReader::letter(std::size_t i, const char *name) {
    return parsed(*this, i, name, parseLetter,
                  QT_TRANSLATE_NOOP("Refusal", "expected one character"));
}

std::optional<double> FieldReader::coordinate(std::size_t i, const char *name, int maxDeg, char pos,
                                              char neg) {
    auto t = s_.field(i);
    auto h = s_.field(i + 1);
    if (t.empty()) return std::nullopt;
    double v;
    if (!parseDegreesMinutes(t, maxDeg, v)) {
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "not a ddmm.mmmm coordinate"));
        return std::nullopt;
    }
    if (h.size() != 1 || (h.front() != pos && h.front() != neg)) {
        fail(i + 1, name, QT_TRANSLATE_NOOP("Refusal", "bad hemisphere"));
        return std::nullopt;
    }
    return h.front() == neg ? -v : v;
}

std::optional<double> FieldReader::latitude(std::size_t i, const char *name) {
    return coordinate(i, name, 90, 'N', 'S');
}

std::optional<double> FieldReader::longitude(std::size_t i, const char *name) {
    return coordinate(i, name, 180, 'E', 'W');
}

std::optional<TimeOfDay> FieldReader::time(std::size_t i, const char *name) {
    return parsed(*this, i, name, parseTimeOfDay,
                  QT_TRANSLATE_NOOP("Refusal", "not an hhmmss.ss time"));
}

std::optional<Date> FieldReader::date(std::size_t i, const char *name) {
    return parsed(*this, i, name, parseDateDdMmYy,
                  QT_TRANSLATE_NOOP("Refusal", "not a ddmmyy date"));
}

} // namespace gnss
