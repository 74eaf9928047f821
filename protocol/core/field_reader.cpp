#include "field_reader.h"

#include <climits>

namespace gnss {

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
    auto t = s_.field(i);
    if (t.empty()) return std::nullopt;
    std::int64_t v;
    if (!parseInt(t, v)) {
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "not an integer"));
        return std::nullopt;
    }
    return v;
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
    auto t = s_.field(i);
    if (t.empty()) return std::nullopt;
    std::uint64_t v;
    if (!parseHex(t, v)) {
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "not hexadecimal"));
        return std::nullopt;
    }
    return v;
}

std::optional<char> FieldReader::letter(std::size_t i, const char *name) {
    auto t = s_.field(i);
    if (t.empty()) return std::nullopt;
    if (t.size() != 1) {
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "expected one character"));
        return std::nullopt;
    }
    return t.front();
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
    auto t = s_.field(i);
    if (t.empty()) return std::nullopt;
    TimeOfDay v;
    if (!parseTimeOfDay(t, v)) {
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "not an hhmmss.ss time"));
        return std::nullopt;
    }
    return v;
}

std::optional<Date> FieldReader::date(std::size_t i, const char *name) {
    auto t = s_.field(i);
    if (t.empty()) return std::nullopt;
    Date v;
    if (!parseDateDdMmYy(t, v)) {
        fail(i, name, QT_TRANSLATE_NOOP("Refusal", "not a ddmmyy date"));
        return std::nullopt;
    }
    return v;
}

} // namespace gnss
