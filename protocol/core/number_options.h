#pragma once
// The options of a setting whose values are a list of numbers (the speeds a port takes), made at
// compile time from that list, so that a receiver family names its speeds once (the dialect
// record's supportedBauds) and its schema's row offers exactly those. Value and label are the
// number as written in decimal ({"4800", "4800"}, ...):
//
//     constexpr int kSupportedBauds[] = {4800, 9600};
//     ... .options = kNumberOptions<kSupportedBauds>, ...
#include "core/settings_schema.h"

#include <array>
#include <cstddef>
#include <string_view>

namespace gnss {

namespace number_options {

// One number in decimal: room for any int with its sign.
struct Text {
    char digits[12] = {};
    std::size_t size = 0;
    constexpr std::string_view view() const { return {digits, size}; }
};

constexpr Text toText(int value) {
    Text t;
    long long v = value;
    if (v < 0) {
        t.digits[t.size++] = '-';
        v = -v;
    }
    char reversed[11] = {};
    std::size_t n = 0;
    do {
        reversed[n++] = static_cast<char>('0' + v % 10);
        v /= 10;
    } while (v > 0);
    while (n > 0) t.digits[t.size++] = reversed[--n];
    return t;
}

template <std::size_t N> constexpr std::array<Text, N> toTexts(const int (&values)[N]) {
    std::array<Text, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = toText(values[i]);
    return out;
}

template <std::size_t N>
constexpr std::array<SettingOption, N> optionsOf(const std::array<Text, N> &texts) {
    std::array<SettingOption, N> out;
    for (std::size_t i = 0; i < N; ++i) out[i] = {texts[i].view(), texts[i].view()};
    return out;
}

// The digits the options point into: one constant per list, for the program's lifetime.
template <const auto &Values> inline constexpr auto kTexts = toTexts(Values);

} // namespace number_options

// The options of an Enum setting whose values are `Values` (a constant array of int).
template <const auto &Values>
inline constexpr auto kNumberOptions = number_options::optionsOf(number_options::kTexts<Values>);

} // namespace gnss
