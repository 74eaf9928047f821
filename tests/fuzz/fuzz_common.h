#pragma once
// What the fuzz harnesses share: reading the input's leading control bytes, cutting the rest
// into pseudo-random chunks, checking JSON syntax, and failing loudly (abort, so that libFuzzer
// and the corpus replayer both stop on the input that broke an invariant).
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

// The harnesses' own checking code is left out of libFuzzer's coverage: its branches say nothing
// about the code under test, and comparing bytes one by one under -fsanitize=fuzzer costs more
// than the decoding it checks.
#if defined(__clang__)
#define GNSS_FUZZ_NO_COVERAGE __attribute__((no_sanitize("coverage")))
#else
#define GNSS_FUZZ_NO_COVERAGE
#endif

namespace gnss::fuzz {

// Reports a broken invariant and aborts.
[[noreturn]] GNSS_FUZZ_NO_COVERAGE inline void fail(const char *what,
                                                    std::string_view detail = {}) {
    std::string shown; // control bytes escaped, at most 4000 bytes
    for (char c : detail.substr(0, 4000)) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 && c != '\n') {
            shown += "\\x";
            shown += "0123456789abcdef"[u >> 4];
            shown += "0123456789abcdef"[u & 15];
        } else {
            shown += c;
        }
    }
    std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
    if (!shown.empty()) std::fprintf(stderr, "  %s\n", shown.c_str());
    std::fflush(stderr);
    std::abort();
}

GNSS_FUZZ_NO_COVERAGE inline void check(bool ok, const char *what, std::string_view detail = {}) {
    if (!ok) fail(what, detail);
}

template <class T> GNSS_FUZZ_NO_COVERAGE void checkEqual(const T &a, const T &b, const char *what) {
    if (!(a == b)) fail(what, std::to_string(a) + " != " + std::to_string(b));
}

// The input, consumed from the front.
class Input {
public:
    Input(const std::uint8_t *data, std::size_t size)
        : p_(reinterpret_cast<const char *>(data)), n_(size) {}

    bool empty() const { return n_ == 0; }
    std::size_t size() const { return n_; }
    // The next byte, or 0 when the input is used up.
    std::uint8_t byte() {
        if (n_ == 0) return 0;
        --n_;
        return static_cast<std::uint8_t>(*p_++);
    }
    // Up to n bytes.
    std::string_view take(std::size_t n) {
        n = std::min(n, n_);
        std::string_view s(p_, n);
        p_ += n;
        n_ -= n;
        return s;
    }
    std::string_view rest() { return take(n_); }

private:
    const char *p_;
    std::size_t n_;
};

// splitmix64: a tiny deterministic generator for chunk sizes.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : s_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }

private:
    std::uint64_t s_;
};

// Cuts `total` bytes into chunks chosen by `seed`: the low 3 bits set the largest chunk
// (1, 2, 4 ... 128 bytes; so byte-at-a-time is one of the choices), the rest seeds the sizes.
// A chunk of 0 bytes is included now and then: feeding nothing must change nothing.
GNSS_FUZZ_NO_COVERAGE inline std::vector<std::size_t> chunking(std::uint8_t seed,
                                                               std::size_t total) {
    const std::size_t largest = std::size_t{1} << (seed & 7);
    Rng rng(seed >> 3);
    std::vector<std::size_t> sizes;
    for (std::size_t done = 0; done < total;) {
        std::size_t n = rng.below(largest + 1);
        if (n == 0 && rng.below(4) != 0) n = 1;
        n = std::min(n, total - done);
        sizes.push_back(n);
        done += n;
    }
    return sizes;
}

// True when `s` is one JSON value (RFC 8259 syntax; depth limited), with nothing after it.
class JsonSyntax {
public:
    GNSS_FUZZ_NO_COVERAGE static bool valid(std::string_view s) {
        JsonSyntax j(s);
        return j.value(0) && (j.skipWs(), j.i_ == s.size());
    }

private:
    GNSS_FUZZ_NO_COVERAGE explicit JsonSyntax(std::string_view s) : s_(s) {}
    GNSS_FUZZ_NO_COVERAGE void skipWs() {
        while (i_ < s_.size() &&
               (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t'))
            ++i_;
    }
    GNSS_FUZZ_NO_COVERAGE bool lit(std::string_view w) {
        if (s_.substr(i_, w.size()) != w) return false;
        i_ += w.size();
        return true;
    }
    GNSS_FUZZ_NO_COVERAGE bool digits() {
        const std::size_t from = i_;
        while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
        return i_ > from;
    }
    GNSS_FUZZ_NO_COVERAGE bool number() {
        if (i_ < s_.size() && s_[i_] == '-') ++i_;
        if (i_ < s_.size() && s_[i_] == '0')
            ++i_;
        else if (!digits())
            return false;
        if (i_ < s_.size() && s_[i_] == '.' && (++i_, !digits())) return false;
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            ++i_;
            if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
            if (!digits()) return false;
        }
        return true;
    }
    GNSS_FUZZ_NO_COVERAGE bool string() {
        if (!lit("\"")) return false;
        while (i_ < s_.size()) {
            const auto c = static_cast<unsigned char>(s_[i_++]);
            if (c == '"') return true;
            if (c < 0x20) return false;
            if (c == '\\') {
                if (i_ >= s_.size()) return false;
                const char e = s_[i_++];
                if (e == 'u') {
                    for (int k = 0; k < 4; ++k, ++i_)
                        if (i_ >= s_.size() || !std::isxdigit(static_cast<unsigned char>(s_[i_])))
                            return false;
                } else if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) {
                    return false;
                }
            }
        }
        return false;
    }
    GNSS_FUZZ_NO_COVERAGE bool value(int depth) {
        if (depth > 64) return false;
        skipWs();
        if (i_ >= s_.size()) return false;
        switch (s_[i_]) {
        case '{': {
            ++i_;
            skipWs();
            if (lit("}")) return true;
            do {
                skipWs();
                if (!string()) return false;
                skipWs();
                if (!lit(":") || !value(depth + 1)) return false;
                skipWs();
            } while (lit(","));
            return lit("}");
        }
        case '[': {
            ++i_;
            skipWs();
            if (lit("]")) return true;
            do {
                if (!value(depth + 1)) return false;
                skipWs();
            } while (lit(","));
            return lit("]");
        }
        case '"': return string();
        case 't': return lit("true");
        case 'f': return lit("false");
        case 'n': return lit("null");
        default: return number();
        }
    }
    std::string_view s_;
    std::size_t i_ = 0;
};

GNSS_FUZZ_NO_COVERAGE inline void checkJson(std::string_view json, const char *what) {
    if (!JsonSyntax::valid(json)) fail(what, json);
}

} // namespace gnss::fuzz
