#pragma once
// Small helpers shared by the RTCM suites (and the fuzz seeds): hex fixtures, MSM masks and
// headers, ephemerides, frames ↔ payloads.
#include "rtcm/rtcm_framer.h"
#include "rtcm/rtcm_messages.h"

#include <bit>
#include <cctype>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rtcm_test {

// "D3 00 13 3E ..." → bytes (spaces ignored).
inline std::string fromHex(std::string_view hex) {
    std::string out;
    int high = -1;
    for (const char c : hex) {
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        const int v = std::isdigit(static_cast<unsigned char>(c))
                              ? c - '0'
                              : std::toupper(static_cast<unsigned char>(c)) - 'A' + 10;
        if (high < 0) {
            high = v;
        } else {
            out.push_back(static_cast<char>(high << 4 | v));
            high = -1;
        }
    }
    return out;
}

// An MSM satellite mask with the given satellite ids (1..64) set, the first id the highest bit.
inline std::uint64_t satMask(std::initializer_list<unsigned> ids) {
    std::uint64_t m = 0;
    for (const unsigned id : ids) m |= std::uint64_t(1) << (64 - id);
    return m;
}

// An MSM signal mask with the given signal ids (1..32) set, the first id the highest bit.
inline std::uint32_t sigMask(std::initializer_list<unsigned> ids) {
    std::uint32_t m = 0;
    for (const unsigned id : ids) m |= std::uint32_t(1) << (32 - id);
    return m;
}

// An MSM header of `type` with these masks and not every satellite on every signal (every third
// cell dropped); what follows from the type: a multiple message on even types, IODS = type,
// smoothing above MSM4. Station, epoch and the rest are the caller's.
inline gnss::rtcm::MsmHeader msmHeader(gnss::rtcm::System s, unsigned type,
                                       std::uint64_t satelliteMask, std::uint32_t signalMask) {
    gnss::rtcm::MsmHeader h;
    h.system = s;
    h.msmType = type;
    h.satelliteMask = satelliteMask;
    h.signalMask = signalMask;
    const unsigned cells = unsigned(std::popcount(satelliteMask) * std::popcount(signalMask));
    for (unsigned i = 0; i < cells; ++i)
        if (i % 3 != 1) h.cellMask |= std::uint64_t(1) << i;
    h.multipleMessage = type % 2 == 0;
    h.iods = type;
    h.smoothing = type > 4;
    return h;
}

// An ephemeris's identifying fields, in Ephemeris's order (GPS, QZSS and BeiDou send them all,
// Galileo no IODC or health); GLONASS's and Galileo's own fields are the caller's.
inline gnss::rtcm::Ephemeris ephemeris(unsigned satellite, std::optional<unsigned> week,
                                       std::optional<unsigned> iode, std::optional<unsigned> iodc,
                                       std::optional<std::uint32_t> toc,
                                       std::optional<std::uint32_t> toe,
                                       std::optional<unsigned> health) {
    return {.satellite = satellite,
            .week = week,
            .iode = iode,
            .iodc = iodc,
            .tocSeconds = toc,
            .toeSeconds = toe,
            .health = health};
}

inline std::span<const std::uint8_t> bytesOf(std::string_view s) {
    return {reinterpret_cast<const std::uint8_t *>(s.data()), s.size()};
}

// The payload of one whole frame (header and CRC dropped).
inline std::span<const std::uint8_t> payloadOf(std::string_view frame) {
    return bytesOf(frame.substr(3, frame.size() - 6));
}

inline gnss::rtcm::RtcmMessage decodeFrame(std::string_view frame) {
    return gnss::rtcm::decodeMessage(payloadOf(frame));
}

// Every frame the framer finds in `data` fed in chunks of the given sizes (cycled).
struct Framed {
    std::vector<std::string> frames;
    gnss::rtcm::RtcmFramerStats stats;
};

inline Framed frameInChunks(std::string_view data, const std::vector<std::size_t> &sizes) {
    gnss::rtcm::RtcmFramer framer;
    Framed r;
    auto keep = [&r](const gnss::rtcm::RtcmFrame &f) {
        r.frames.emplace_back(reinterpret_cast<const char *>(f.bytes.data()), f.bytes.size());
    };
    std::size_t pos = 0, k = 0;
    while (pos < data.size()) {
        const std::size_t n =
                std::min(std::max<std::size_t>(sizes[k++ % sizes.size()], 1), data.size() - pos);
        framer.feed(data.substr(pos, n), keep);
        pos += n;
    }
    framer.finish(keep);
    r.stats = framer.stats();
    return r;
}

inline Framed frameWhole(std::string_view data) {
    return frameInChunks(data, {data.size() + 1});
}

} // namespace rtcm_test
