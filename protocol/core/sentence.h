#pragma once
// Sentence: one framed line split into address and fields, with its checksum checked.
//
//   $GPGGA,123519,4807.038,N,...,*47
//   ^ start   ^ fields (after the address)  ^ checksum
//
// Parsing never allocates and never throws: fields are offsets into the line, which the caller
// keeps alive. Leading and trailing blanks of a field are trimmed on access (Nemerix and the
// GeoStar spec print blanks after commas).
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace gnss {

enum class ChecksumStatus : std::uint8_t { Ok, Bad, Missing };

std::string_view toString(ChecksumStatus s);

// XOR of every byte of `body` (the text between the start character and '*').
std::uint8_t nmeaChecksum(std::string_view body);

class Sentence {
public:
    static constexpr std::size_t kMaxFields = 255;

    // Parses `line` (from '$' or '!' to before the terminator). Returns false when the line is
    // not a sentence at all (no address, too many fields); `error()` then says why.
    bool parse(std::string_view line);

    std::string_view line() const { return line_; }
    char start() const { return line_.empty() ? '\0' : line_.front(); }
    // Text between the start character and '*' (what the checksum covers).
    std::string_view body() const { return body_; }

    // Address as received ("GPGGA", "PNVGRTK", "GPSGG").
    std::string_view address() const { return address_; }
    // Standard address: talker = first two characters, type = the rest ("GP" + "GGA").
    // Proprietary address: talker "P", type = the rest ("P" + "NVGRTK").
    // Inline: every GSV and GSA asks for its talker.
    std::string_view talker() const {
        if (proprietary()) return address_.substr(0, 1);
        return address_.substr(0, address_.size() >= 2 ? 2 : address_.size());
    }
    std::string_view type() const {
        if (proprietary()) return address_.substr(1);
        return address_.size() > 2 ? address_.substr(2) : std::string_view{};
    }
    bool proprietary() const { return !address_.empty() && address_.front() == 'P'; }

    ChecksumStatus checksum() const { return checksumStatus_; }
    std::uint8_t declaredChecksum() const { return declared_; }
    std::uint8_t computedChecksum() const { return computed_; }
    // The checksum text was a placeholder ("*xx", "*XX", "*") rather than absent.
    bool checksumPlaceholder() const { return placeholder_; }

    // Fields after the address, 0-based. field(i) past the end is an empty view.
    std::size_t fieldCount() const { return fieldCount_; }
    std::string_view field(std::size_t i) const {
        if (i >= fieldCount_) return {};
        const std::string_view f(body_.data() + start_[i], start_[i + 1] - start_[i] - 1u);
        return hasBlank_ ? trim(f) : f; // most sentences have no blank at all: skip trimming
    }
    // Untrimmed text of a field, for the few places where inner blanks matter.
    std::string_view rawField(std::size_t i) const {
        if (i >= fieldCount_) return {};
        return body_.substr(start_[i], start_[i + 1] - start_[i] - 1);
    }

    // The text of fields i to i + count - 1 with the commas between them, untrimmed; empty when
    // they are not all there.
    std::string_view fieldRun(std::size_t i, std::size_t count) const {
        if (count == 0 || i + count > fieldCount_) return {};
        return body_.substr(start_[i], start_[i + count] - start_[i] - 1u);
    }

    // Field i when it is empty or one to three digits, the commonest fields of all (satellite
    // ids, elevations, azimuths, SNRs, counts), read without making a view of it first:
    // kSmallNumber (in `out`), kEmpty (or past the end), or kOther (anything else: read it as
    // text).
    enum SmallField { kEmpty, kSmallNumber, kOther };
    SmallField smallField(std::size_t i, int &out) const {
        if (i >= fieldCount_) return kEmpty;
        const unsigned from = start_[i], length = start_[i + 1] - from - 1u;
        const auto *p = reinterpret_cast<const unsigned char *>(body_.data()) + from;
        switch (length) {
        case 0: return kEmpty;
        case 1: {
            const unsigned a = p[0] - unsigned{'0'};
            if (a > 9) return kOther;
            out = static_cast<int>(a);
            return kSmallNumber;
        }
        case 2: {
            const unsigned a = p[0] - unsigned{'0'}, b = p[1] - unsigned{'0'};
            if ((a > 9) | (b > 9)) return kOther;
            out = static_cast<int>(a * 10 + b);
            return kSmallNumber;
        }
        case 3: {
            const unsigned a = p[0] - unsigned{'0'}, b = p[1] - unsigned{'0'},
                           c = p[2] - unsigned{'0'};
            if ((a > 9) | (b > 9) | (c > 9)) return kOther;
            out = static_cast<int>(a * 100 + b * 10 + c);
            return kSmallNumber;
        }
        default: return kOther;
        }
    }

    const char *error() const { return error_; }

    // `s` without the spaces around it (what field() does to a field).
    static std::string_view trim(std::string_view s) {
        while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
        while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
        return s;
    }

private:
    std::string_view line_;
    std::string_view body_;
    std::string_view address_;
    const char *error_ = nullptr;
    std::size_t fieldCount_ = 0;
    ChecksumStatus checksumStatus_ = ChecksumStatus::Missing;
    std::uint8_t declared_ = 0;
    std::uint8_t computed_ = 0;
    bool placeholder_ = false;
    bool hasBlank_ = false;
    // start_[i] = offset in body_ of field i; start_[fieldCount_] = body_.size() + 1.
    // Deliberately not initialised: parse() writes what it uses.
    std::uint16_t start_[kMaxFields + 1];
};

} // namespace gnss
