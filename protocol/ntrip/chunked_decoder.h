#pragma once
// ChunkedDecoder: an HTTP/1.1 "Transfer-Encoding: chunked" body back to the bytes sent, as
// NTRIP 2 casters deliver their streams.
//
//   1a;name=value CR LF      chunk size in hex, optional extensions (ignored)
//   <0x1a data bytes> CR LF
//   ...
//   0 CR LF                  the last chunk: the stream ends
//   [trailer lines] CR LF
//
// Incremental and chunking-invariant: the boundaries of what it is fed (TCP segments) may fall
// anywhere, inside a size line, inside the data, between CR and LF. A bare LF is accepted where
// CR LF belongs (lenient, as most HTTP clients are). Malformed input (a size that is not hex or
// too large, data not followed by CR LF) stops it with an error text; it never throws.
#include <cstdint>
#include <string>
#include <string_view>

namespace gnss::ntrip {

class ChunkedDecoder {
public:
    enum class Status : std::uint8_t {
        Ok,       // more chunks may come
        Finished, // the 0 chunk arrived: the body is complete
        Error,    // malformed; error() says how. Nothing more is decoded.
    };
    static constexpr std::uint64_t kMaxChunk = std::uint64_t(1) << 32; // 8 hex digits
    static constexpr std::size_t kMaxLine = 4096; // size line extensions, trailer lines

    // Appends the decoded bytes of `in` to `out`.
    Status feed(std::string_view in, std::string &out);

    Status status() const { return status_; }
    const std::string &error() const { return error_; }
    std::uint64_t chunks() const { return chunks_; }          // data chunks begun
    std::uint64_t bytesDecoded() const { return decoded_; }   // bytes handed out
    std::uint64_t bytesAfterEnd() const { return afterEnd_; } // fed after the last chunk

private:
    enum class State : std::uint8_t {
        SizeStart,
        Size,
        SizeSpace,
        Extension,
        SizeLf,
        Data,
        DataCr,
        DataLf,
        TrailerStart,
        Trailer,
        TrailerEndLf,
        Done,
        Failed,
    };
    // Stops decoding with the reason and the byte that broke it; returns Status::Error.
    Status fail(std::string why, char c);

    State state_ = State::SizeStart;
    Status status_ = Status::Ok;
    std::string error_;
    std::uint64_t size_ = 0;     // the chunk size being read, then the data bytes left
    std::size_t lineLength_ = 0; // of an extension or trailer line
    std::uint64_t chunks_ = 0;
    std::uint64_t decoded_ = 0;
    std::uint64_t afterEnd_ = 0;
};

} // namespace gnss::ntrip
