#include "ntrip/source_table.h"

#include "ntrip/text_util.h"

#include <charconv>
#include <cmath>
#include <type_traits>

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

// The whole field as an int or a (finite) double; none when it is anything more or less.
template <class T> std::optional<T> numeric(const std::vector<std::string_view> &f, std::size_t i) {
    if (i >= f.size()) return std::nullopt;
    const std::string_view s = trim(f[i]);
    T v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(v)) return std::nullopt;
    return v;
}

bool yes(const std::vector<std::string_view> &f, std::size_t i) {
    const std::string t = text(f, i);
    return t == "1" || t == "Y" || t == "y";
}

// A field read as its member's type.
void read(const std::vector<std::string_view> &f, std::size_t i, std::string &out) {
    out = text(f, i);
}
template <class T>
void read(const std::vector<std::string_view> &f, std::size_t i, std::optional<T> &out) {
    out = numeric<T>(f, i);
}
void read(const std::vector<std::string_view> &f, std::size_t i, bool &out) {
    out = yes(f, i);
}

// Latitude and longitude only when they can be a place on Earth.
void checkPosition(std::optional<double> &lat, std::optional<double> &lon) {
    if (lat && std::fabs(*lat) > 90) lat.reset();
    if (lon && (*lon < -180 || *lon > 360)) lon.reset(); // some tables use 0..360 east
    if (lon && *lon > 180) *lon -= 360;
}

// A record read field by field into `into`; one without a name (its first field) is a bad line,
// one missing more than its last field (misc, often left off entirely) is short.
template <class Entry>
void addRecord(std::string_view line, std::span<const RecordField<Entry>> fields,
               std::vector<Entry> &into, SourceTable &table) {
    const auto f = splitFields(line, fields.size() + 1);
    Entry e;
    for (std::size_t i = 0; i < fields.size(); ++i)
        std::visit([&](auto member) { read(f, i + 1, e.*member); }, fields[i].member);
    if constexpr (requires { e.latitude; }) checkPosition(e.latitude, e.longitude);
    if ((e.*std::get<std::string Entry::*>(fields[0].member)).empty()) {
        ++table.badLines;
        return;
    }
    if (f.size() < fields.size()) ++table.shortRecords;
    into.push_back(std::move(e));
}

} // namespace

std::span<const RecordField<StreamEntry>> streamFields() {
    using E = StreamEntry;
    static const RecordField<E> fields[] = {
            {"mountpoint", &E::mountpoint},
            {"identifier", &E::identifier},
            {"format", &E::format},
            {"format_details", &E::formatDetails},
            {"carrier", &E::carrier},
            {"nav_system", &E::navSystem},
            {"network", &E::network},
            {"country", &E::country},
            {"latitude", &E::latitude},
            {"longitude", &E::longitude},
            {"nmea", &E::wantsGga},
            {"solution", &E::solution},
            {"generator", &E::generator},
            {"compression", &E::compression},
            {"authentication", &E::authentication},
            {"fee", &E::fee},
            {"bitrate", &E::bitrate},
            {"misc", &E::misc},
    };
    return fields;
}

std::span<const RecordField<CasterEntry>> casterFields() {
    using E = CasterEntry;
    static const RecordField<E> fields[] = {
            {"host", &E::host},
            {"port", &E::port},
            {"identifier", &E::identifier},
            {"operator", &E::casterOperator},
            {"nmea", &E::nmea},
            {"country", &E::country},
            {"latitude", &E::latitude},
            {"longitude", &E::longitude},
            {"fallback_host", &E::fallbackHost},
            {"fallback_port", &E::fallbackPort},
            {"misc", &E::misc},
    };
    return fields;
}

std::span<const RecordField<NetworkEntry>> networkFields() {
    using E = NetworkEntry;
    static const RecordField<E> fields[] = {
            {"identifier", &E::identifier},
            {"operator", &E::networkOperator},
            {"authentication", &E::authentication},
            {"fee", &E::fee},
            {"web_net", &E::webNet},
            {"web_str", &E::webStr},
            {"web_reg", &E::webReg},
            {"misc", &E::misc},
    };
    return fields;
}

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
    if (records < kMaxRecords) {
        if (tag == "STR;") return addRecord(l, streamFields(), table_.streams, table_);
        if (tag == "CAS;") return addRecord(l, casterFields(), table_.casters, table_);
        if (tag == "NET;") return addRecord(l, networkFields(), table_.networks, table_);
    }
    ++table_.badLines; // no record, or one too many
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
