#include "faults.h"

#include <charconv>
#include <cmath>

namespace gnss::sim {

namespace {

bool parseNumber(std::string_view text, double &out) {
    if (text.empty()) return false;
    const char *end = text.data() + text.size();
    auto [p, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && p == end && std::isfinite(out);
}

} // namespace

bool FaultSpec::any() const {
    return badChecksum > 0 || truncate > 0 || binary > 0 || silenceAt >= 0 || !noReply.empty() ||
           slowReplyMs > 0 || hangupAfter >= 0;
}

bool FaultSpec::silentAt(double time) const {
    if (silenceAt < 0 || silenceFor <= 0 || time < silenceAt) return false;
    double t = time - silenceAt;
    if (silenceEvery > 0) t = std::fmod(t, silenceEvery);
    return t < silenceFor;
}

bool FaultSpec::replySuppressed(std::string_view address, std::string_view firstField) const {
    for (const std::string &n : noReply)
        if (n == address || (!firstField.empty() && n == firstField)) return true;
    return false;
}

std::optional<FaultSpec> parseFaults(std::string_view spec, std::string &error) {
    FaultSpec f;
    while (!spec.empty()) {
        const auto comma = spec.find(',');
        std::string_view item = spec.substr(0, comma);
        spec = comma == std::string_view::npos ? std::string_view() : spec.substr(comma + 1);
        if (item.empty()) continue;
        const auto eq = item.find('=');
        const std::string_view key = item.substr(0, eq);
        const std::string_view value =
                eq == std::string_view::npos ? std::string_view() : item.substr(eq + 1);
        auto probability = [&](double &out) {
            if (!parseNumber(value, out) || out < 0 || out > 1) {
                error = std::string(key) + ": expected a probability 0..1, got '" +
                        std::string(value) + "'";
                return false;
            }
            return true;
        };
        auto seconds = [&](std::string_view v, double &out, std::string_view what) {
            if (!parseNumber(v, out) || out < 0) {
                error = std::string(key) + ": expected " + std::string(what) +
                        " (a number >= 0), got '" + std::string(v) + "'";
                return false;
            }
            return true;
        };
        if (key == "badcs") {
            if (!probability(f.badChecksum)) return std::nullopt;
        } else if (key == "truncate") {
            if (!probability(f.truncate)) return std::nullopt;
        } else if (key == "binary") {
            if (!probability(f.binary)) return std::nullopt;
        } else if (key == "silence") {
            // D@T or D@T/P: D seconds of silence from time T, repeated every P seconds.
            const auto at = value.find('@');
            if (at == std::string_view::npos) {
                error = "silence: expected SECONDS@START[/EVERY], got '" + std::string(value) + "'";
                return std::nullopt;
            }
            std::string_view start = value.substr(at + 1);
            std::string_view every;
            if (const auto slash = start.find('/'); slash != std::string_view::npos) {
                every = start.substr(slash + 1);
                start = start.substr(0, slash);
            }
            if (!seconds(value.substr(0, at), f.silenceFor, "a duration in seconds") ||
                !seconds(start, f.silenceAt, "a start time in seconds") ||
                (!every.empty() && !seconds(every, f.silenceEvery, "a period in seconds")))
                return std::nullopt;
            if (!every.empty() && f.silenceEvery <= f.silenceFor) {
                error = "silence: the period must be longer than the silence";
                return std::nullopt;
            }
        } else if (key == "noreply") {
            std::string_view list = value;
            while (!list.empty()) {
                const auto plus = list.find('+');
                const auto name = list.substr(0, plus);
                if (!name.empty()) f.noReply.emplace_back(name);
                list = plus == std::string_view::npos ? std::string_view() : list.substr(plus + 1);
            }
            if (f.noReply.empty()) {
                error = "noreply: expected command names joined with '+' (PNVGRTK+RQUERY)";
                return std::nullopt;
            }
        } else if (key == "slowreply") {
            if (!seconds(value, f.slowReplyMs, "a delay in milliseconds")) return std::nullopt;
        } else if (key == "hangup") {
            if (!seconds(value, f.hangupAfter, "a time in seconds")) return std::nullopt;
        } else {
            error = "unknown fault '" + std::string(key) +
                    "' (known: badcs, truncate, binary, silence, noreply, slowreply, hangup)";
            return std::nullopt;
        }
    }
    return f;
}

std::uint32_t crc24q(std::string_view bytes) {
    std::uint32_t crc = 0;
    for (unsigned char b : bytes) {
        crc ^= static_cast<std::uint32_t>(b) << 16;
        for (int i = 0; i < 8; ++i) {
            crc <<= 1;
            if (crc & 0x1000000) crc ^= 0x1864CFB;
        }
    }
    return crc & 0xFFFFFF;
}

std::string rtcm3Frame(std::mt19937 &rng, int messageNumber, int payloadLength) {
    if (payloadLength < 2) payloadLength = 2;
    if (payloadLength > 1023) payloadLength = 1023;
    std::string f;
    f.push_back(static_cast<char>(0xD3));
    f.push_back(static_cast<char>((payloadLength >> 8) & 0x03));
    f.push_back(static_cast<char>(payloadLength & 0xFF));
    f.push_back(static_cast<char>((messageNumber >> 4) & 0xFF));
    std::uniform_int_distribution<int> byte(0, 255);
    f.push_back(static_cast<char>(((messageNumber & 0x0F) << 4) | (byte(rng) & 0x0F)));
    for (int i = 2; i < payloadLength; ++i) f.push_back(static_cast<char>(byte(rng)));
    const std::uint32_t crc = crc24q(f);
    f.push_back(static_cast<char>((crc >> 16) & 0xFF));
    f.push_back(static_cast<char>((crc >> 8) & 0xFF));
    f.push_back(static_cast<char>(crc & 0xFF));
    return f;
}

} // namespace gnss::sim
