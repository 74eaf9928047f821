#pragma once
// One hexadecimal digit's value, for the parsers of checksums, hex fields and chunk sizes.

namespace gnss {

// 0 to 15 for '0'-'9', 'A'-'F' and 'a'-'f'; -1 for any other character.
// A table, not three comparisons: a checksum's two digits are read on every sentence, and
// whether each is a letter or a figure is a coin toss for a branch predictor.
inline constexpr auto kHexDigitValues = [] {
    struct Table {
        signed char v[256];
    } t{};
    for (int c = 0; c < 256; ++c)
        t.v[c] = static_cast<signed char>(c >= '0' && c <= '9'   ? c - '0'
                                          : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                          : c >= 'a' && c <= 'f' ? c - 'a' + 10
                                                                 : -1);
    return t;
}();

constexpr int hexDigitValue(char c) {
    return kHexDigitValues.v[static_cast<unsigned char>(c)];
}

} // namespace gnss
