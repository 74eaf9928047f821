#include "source_table.h"

#include "text_util.h"

#include <charconv>
#include <cmath>

namespace gnss::ntrip {

namespace {

// Fields split at ';', at most `count`: the last keeps the rest of the line (misc may hold ';').
std::vector<std::string_view> splitFields(std::string_view line, std::size_t count) {
    std::vector<std::string_view> out;
    while (out.size() + 1 < count) {
        const auto semi = line.find(';');
        if (semi == std::string_view::npos) break;
        out.push_back(line.substr(0, semi));
        line.remove_prefix(semi + 1);
    }
    out.push_back(line);
    return out;
}

std::string text(const std::vector<std::string_view> &f, std::size_t i) {
    return i < f.size() ? std::string(trim(f[i])) : std::string();
}

std::optional<double> number(const std::vector<std::string_view> &f, std::size_t i) {
    if (i >= f.size()) return std::nullopt;
    const std::string_view s = trim(f[i]);
    double v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<int> integer(const std::vector<std::string_view> &f, std::size_t i) {
    if (i >= f.size()) return std::nullopt;
    const std::string_view s = trim(f[i]);
    int v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
    return v;
}

bool yes(const std::vector<std::string_view> &f, std::size_t i) {
    const std::string t = text(f, i);
    return t == "1" || t == "Y" || t == "y";
}

// Latitude and longitude only when they can be a place on Earth.
void position(const std::vector<std::string_view> &f, std::size_t i, std::optional<double> &lat,
              std::optional<double> &lon) {
    lat = number(f, i);
    lon = number(f, i + 1);
    if (lat && std::fabs(*lat) > 90) lat.reset();
    if (lon && (*lon < -180 || *lon > 360)) lon.reset(); // some tables use 0..360 east
    if (lon && *lon > 180) *lon -= 360;
}

} // namespace

const StreamEntry *SourceTable::find(std::string_view mountpoint) const {
    for (const StreamEntry &s : streams)
        if (s.mountpoint == mountpoint) return &s;
    return nullptr;
}

void SourceTableParser::feed(std::string_view bytes) {
    while (!bytes.empty()) {
        const auto nl = bytes.find('\n');
        const std::string_view piece = bytes.substr(0, nl);
        if (!overlong_) {
            if (line_.size() + piece.size() > kMaxLine) {
                overlong_ = true;
                line_.clear();
            } else {
                line_.append(piece);
            }
        }
        if (nl == std::string_view::npos) return;
        bytes.remove_prefix(nl + 1);
        if (overlong_) {
            ++table_.longLines;
            overlong_ = false;
        } else {
            line(line_);
        }
        line_.clear();
    }
}

void SourceTableParser::finish() {
    if (overlong_) {
        ++table_.longLines;
        overlong_ = false;
    } else if (!line_.empty()) {
        line(line_);
    }
    line_.clear();
}

void SourceTableParser::line(std::string_view l) {
    l = trim(l);
    if (l.empty()) return;
    if (l == "ENDSOURCETABLE") {
        table_.complete = true;
        return;
    }
    const std::size_t records =
            table_.streams.size() + table_.casters.size() + table_.networks.size();
    const std::string_view tag = l.substr(0, 4);
    if (records >= kMaxRecords || (tag != "STR;" && tag != "CAS;" && tag != "NET;")) {
        ++table_.badLines;
        return;
    }
    if (tag == "STR;") {
        const auto f = splitFields(l, 19);
        StreamEntry s;
        s.mountpoint = text(f, 1);
        if (s.mountpoint.empty()) {
            ++table_.badLines;
            return;
        }
        if (f.size() < 18) ++table_.shortRecords; // misc (19th) is often left off entirely
        s.identifier = text(f, 2);
        s.format = text(f, 3);
        s.formatDetails = text(f, 4);
        s.carrier = integer(f, 5);
        s.navSystem = text(f, 6);
        s.network = text(f, 7);
        s.country = text(f, 8);
        position(f, 9, s.latitude, s.longitude);
        s.wantsGga = yes(f, 11);
        s.solution = integer(f, 12);
        s.generator = text(f, 13);
        s.compression = text(f, 14);
        s.authentication = text(f, 15);
        s.fee = yes(f, 16);
        s.bitrate = integer(f, 17);
        s.misc = text(f, 18);
        table_.streams.push_back(std::move(s));
    } else if (tag == "CAS;") {
        const auto f = splitFields(l, 12);
        CasterEntry c;
        c.host = text(f, 1);
        if (c.host.empty()) {
            ++table_.badLines;
            return;
        }
        if (f.size() < 11) ++table_.shortRecords;
        c.port = integer(f, 2);
        c.identifier = text(f, 3);
        c.casterOperator = text(f, 4);
        c.nmea = yes(f, 5);
        c.country = text(f, 6);
        position(f, 7, c.latitude, c.longitude);
        c.fallbackHost = text(f, 9);
        c.fallbackPort = integer(f, 10);
        c.misc = text(f, 11);
        table_.casters.push_back(std::move(c));
    } else {
        const auto f = splitFields(l, 9);
        NetworkEntry n;
        n.identifier = text(f, 1);
        if (n.identifier.empty()) {
            ++table_.badLines;
            return;
        }
        if (f.size() < 8) ++table_.shortRecords;
        n.networkOperator = text(f, 2);
        n.authentication = text(f, 3);
        n.fee = yes(f, 4);
        n.webNet = text(f, 5);
        n.webStr = text(f, 6);
        n.webReg = text(f, 7);
        n.misc = text(f, 8);
        table_.networks.push_back(std::move(n));
    }
}

SourceTable parseSourceTable(std::string_view text) {
    SourceTableParser p;
    p.feed(text);
    p.finish();
    return p.take();
}

bool isRtcm3Format(std::string_view format) {
    std::string compact;
    for (char c : format)
        if (c != ' ' && c != '_' && c != '-') compact.push_back(lowerAscii(c));
    return compact.rfind("rtcm3", 0) == 0;
}

} // namespace gnss::ntrip
