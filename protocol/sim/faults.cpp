#include "sim/faults.h"

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

// Whether a command of `address` whose first field is `firstField` is one of `names`.
bool named(const std::vector<std::string> &names, std::string_view address,
           std::string_view firstField) {
    for (const std::string &n : names)
        if (n == address || (!firstField.empty() && n == firstField)) return true;
    return false;
}

// "A+B+C" → A, B, C (empty names left out); false when none is given.
bool commandNames(std::string_view list, std::vector<std::string> &out) {
    while (!list.empty()) {
        const auto plus = list.find('+');
        const auto name = list.substr(0, plus);
        if (!name.empty()) out.emplace_back(name);
        list = plus == std::string_view::npos ? std::string_view() : list.substr(plus + 1);
    }
    return !out.empty();
}

} // namespace

bool FaultSpec::any() const {
    return badChecksum > 0 || truncate > 0 || binary > 0 || junkPerSecond > 0 || silenceAt >= 0 ||
           !noReply.empty() || slowReplyMs > 0 || hangupAfter >= 0 || !powerCut.empty() ||
           !hangupOn.empty();
}

bool FaultSpec::silentAt(double time) const {
    if (silenceAt < 0 || silenceFor <= 0 || time < silenceAt) return false;
    double t = time - silenceAt;
    if (silenceEvery > 0) t = std::fmod(t, silenceEvery);
    return t < silenceFor;
}

bool FaultSpec::replySuppressed(std::string_view address, std::string_view firstField) const {
    return named(noReply, address, firstField);
}

bool FaultSpec::cutsPower(std::string_view address, std::string_view firstField) const {
    return named(powerCut, address, firstField);
}

bool FaultSpec::hangsUpOn(std::string_view address, std::string_view firstField) const {
    return named(hangupOn, address, firstField);
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
        } else if (key == "junk") {
            double rate = 0;
            if (!parseNumber(value, rate) || rate <= 0 || rate > 1e6) {
                error = "junk: expected bytes per second 1..1000000, got '" + std::string(value) +
                        "'";
                return std::nullopt;
            }
            f.junkPerSecond = rate;
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
        } else if (key == "noreply" || key == "powercut") {
            if (!commandNames(value, key == "noreply" ? f.noReply : f.powerCut)) {
                error = std::string(key) +
                        ": expected command names joined with '+' (PNVGRTK+RQUERY)";
                return std::nullopt;
            }
        } else if (key == "hangupon") {
            // CMD[+CMD][/DOWN]: the line drops when the first of them arrives, back DOWN s later.
            std::string_view names = value;
            if (const auto slash = value.find('/'); slash != std::string_view::npos) {
                names = value.substr(0, slash);
                if (!seconds(value.substr(slash + 1), f.hangupOnDown, "a time down in seconds"))
                    return std::nullopt;
                if (f.hangupOnDown <= 0) {
                    error = "hangupon: the time down must be > 0";
                    return std::nullopt;
                }
            }
            if (!commandNames(names, f.hangupOn)) {
                error = "hangupon: expected command names joined with '+' and an optional "
                        "/SECONDS down (PNVGPPS/1)";
                return std::nullopt;
            }
        } else if (key == "slowreply") {
            if (!seconds(value, f.slowReplyMs, "a delay in milliseconds")) return std::nullopt;
        } else if (key == "hangup") {
            // T, or T/DOWN[xCOUNT]: down DOWN seconds after T with a program on the line.
            std::string_view after = value, down, times;
            bool counted = false;
            double count = 0;
            if (const auto slash = after.find('/'); slash != std::string_view::npos) {
                down = after.substr(slash + 1);
                after = after.substr(0, slash);
                if (const auto x = down.find('x'); x != std::string_view::npos) {
                    times = down.substr(x + 1);
                    down = down.substr(0, x);
                    counted = true;
                }
            }
            if (!seconds(after, f.hangupAfter, "a time in seconds") ||
                (!down.empty() && !seconds(down, f.hangupDown, "a time down in seconds")))
                return std::nullopt;
            if (value.find('/') != std::string_view::npos && f.hangupDown <= 0) {
                error = "hangup: expected SECONDS[/DOWN[xCOUNT]] with DOWN > 0, got '" +
                        std::string(value) + "'";
                return std::nullopt;
            }
            if (counted && (!parseNumber(times, count) || count < 1 || count != std::floor(count) ||
                            count > 1e6)) {
                error = "hangup: expected a count 1..1000000 after 'x', got '" +
                        std::string(times) + "'";
                return std::nullopt;
            }
            f.hangupTimes = static_cast<int>(count);
        } else {
            error = "unknown fault '" + std::string(key) +
                    "' (known: badcs, truncate, binary, junk, silence, noreply, slowreply, "
                    "hangup, hangupon, powercut)";
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
