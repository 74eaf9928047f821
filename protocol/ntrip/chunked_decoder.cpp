#include "ntrip/chunked_decoder.h"

#include "core/hex_digit.h"

#include <algorithm>

namespace gnss::ntrip {

namespace {

// The byte quoted in an error text: printable as itself, anything else as hex.
std::string quoted(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x21 && u < 0x7F) return std::string("'") + c + "'";
    static const char hex[] = "0123456789ABCDEF";
    return std::string("0x") + hex[u >> 4] + hex[u & 15];
}

} // namespace

ChunkedDecoder::Status ChunkedDecoder::fail(std::string why, char c) {
    error_ = std::move(why) + " (got " + quoted(c) + ")";
    state_ = State::Failed;
    return status_ = Status::Error;
}

ChunkedDecoder::Status ChunkedDecoder::feed(std::string_view in, std::string &out) {
    std::size_t i = 0;
    while (i < in.size()) {
        const char c = in[i];
        switch (state_) {
        case State::SizeStart:
            if (hexDigitValue(c) < 0) return fail("chunk size is not hexadecimal", c);
            size_ = 0;
            state_ = State::Size;
            [[fallthrough]]; // the first digit is read as the others
        case State::Size:
            if (const int digit = hexDigitValue(c); digit >= 0) {
                size_ = size_ * 16 + static_cast<std::uint64_t>(digit);
                if (size_ >= kMaxChunk) return fail("chunk size too large", c);
                break;
            }
            [[fallthrough]];
        case State::SizeSpace:
            // After the digits: spaces (tolerated), ';' extensions, or the end of the line.
            if (c == ' ' || c == '\t') {
                state_ = State::SizeSpace;
            } else if (c == ';') {
                state_ = State::Extension;
                lineLength_ = 0;
            } else if (c == '\r') {
                state_ = State::SizeLf;
            } else if (c == '\n') {
                state_ = State::SizeLf;
                continue; // handled as the LF below
            } else {
                return fail("chunk size line has a stray character", c);
            }
            break;
        case State::Extension:
            if (c == '\r' || c == '\n') {
                state_ = State::SizeLf;
                if (c == '\n') continue;
            } else if (++lineLength_ > kMaxLine) {
                return fail("chunk extension too long", c);
            }
            break;
        case State::SizeLf:
            if (c != '\n') return fail("chunk size line not ended by CR LF", c);
            if (size_ == 0) {
                state_ = State::TrailerStart;
                status_ = Status::Finished;
            } else {
                state_ = State::Data;
                ++chunks_;
            }
            break;
        case State::Data: {
            const std::size_t n = static_cast<std::size_t>(
                    std::min<std::uint64_t>(size_, static_cast<std::uint64_t>(in.size() - i)));
            out.append(in.substr(i, n));
            decoded_ += n;
            size_ -= n;
            i += n;
            if (size_ == 0) state_ = State::DataCr;
            continue;
        }
        case State::DataCr:
            if (c == '\r') {
                state_ = State::DataLf;
                break;
            }
            [[fallthrough]]; // a bare LF ends the data as CR LF does
        case State::DataLf:
            if (c != '\n') return fail("chunk data not followed by CR LF", c);
            state_ = State::SizeStart;
            break;
        case State::TrailerStart:
            // After "0 CR LF": trailer lines, then an empty line. Tolerated as they come; the
            // body is complete whatever follows.
            if (c == '\r') {
                state_ = State::TrailerEndLf;
            } else if (c == '\n') {
                state_ = State::Done;
            } else {
                state_ = State::Trailer;
                lineLength_ = 1;
            }
            break;
        case State::Trailer:
            if (c == '\n') {
                state_ = State::TrailerStart;
            } else if (++lineLength_ > kMaxLine) {
                state_ = State::Done; // not a trailer: the rest is ignored anyway
                continue;
            }
            break;
        case State::TrailerEndLf:
            state_ = State::Done;
            if (c != '\n') continue; // a lone CR: what follows is after the end
            break;
        case State::Done: afterEnd_ += in.size() - i; return status_;
        case State::Failed: return status_;
        }
        ++i;
    }
    return status_;
}

} // namespace gnss::ntrip
