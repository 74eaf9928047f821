// Sites and the site list: name rules, checks, look-up and merging (site.h).
#include "sites/site.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <ctime>

namespace gnss::sites {
namespace {

// The code point at `at` (advanced past it), or -1 for a malformed sequence.
long nextCodePoint(std::string_view s, std::size_t &at) {
    const auto c = static_cast<unsigned char>(s[at++]);
    if (c < 0x80) return c;
    int extra = c >= 0xF0 && c < 0xF5 ? 3 : c >= 0xE0 ? 2 : c >= 0xC2 && c < 0xE0 ? 1 : -1;
    if (extra < 0 || (c >= 0xF0 && extra != 3)) return -1;
    long cp = c & (0x3F >> extra);
    for (; extra > 0; --extra) {
        if (at >= s.size()) return -1;
        const auto d = static_cast<unsigned char>(s[at++]);
        if ((d & 0xC0) != 0x80) return -1;
        cp = (cp << 6) | (d & 0x3F);
    }
    if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return -1;
    return cp;
}

void appendUtf8(std::string &out, long cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

long lowerCodePoint(long cp) {
    if (cp >= 'A' && cp <= 'Z') return cp + 32;
    if (cp >= 0xC0 && cp <= 0xDE && cp != 0xD7) return cp + 32; // Latin-1
    if (cp >= 0x410 && cp <= 0x42F) return cp + 32;             // Cyrillic А-Я
    if (cp >= 0x400 && cp <= 0x40F) return cp + 80;             // Ѐ-Џ (Ё)
    return cp;
}

bool isControl(long cp) {
    return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0x2028 || cp == 0x2029;
}

bool digitsAt(std::string_view s, std::size_t at, std::size_t n, int &value) {
    if (at + n > s.size()) return false;
    value = 0;
    for (std::size_t i = at; i < at + n; ++i) {
        if (s[i] < '0' || s[i] > '9') return false;
        value = value * 10 + (s[i] - '0');
    }
    return true;
}

// "YYYY-MM-DD", optionally followed by "T" and a time (not checked further).
bool isoDate(std::string_view s) {
    int y = 0, m = 0, d = 0;
    if (!digitsAt(s, 0, 4, y) || s.size() < 10 || s[4] != '-' || !digitsAt(s, 5, 2, m) ||
        s[7] != '-' || !digitsAt(s, 8, 2, d))
        return false;
    if (m < 1 || m > 12 || d < 1 || d > 31) return false;
    if (s.size() == 10) return true;
    return (s[10] == 'T' || s[10] == ' ') && s.size() <= 40;
}

bool siteNameLess(const Site &a, const Site &b) {
    return foldedName(a.name) < foldedName(b.name);
}

} // namespace

std::string decimalText(double v) {
    char b[32];
    const auto r = std::to_chars(b, b + sizeof b, v);
    return r.ec == std::errc() ? std::string(b, r.ptr) : std::string("nan");
}

bool parseDecimal(std::string_view text, double &out) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    if (text.empty()) return false;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
    return r.ec == std::errc() && r.ptr == text.data() + text.size() && std::isfinite(out);
}

wgs84::Geodetic Site::antennaReferencePoint() const {
    return {latDeg, lonDeg, height.value_or(0.0) + antennaHeight};
}

wgs84::Ecef Site::antennaReferenceEcef() const {
    return wgs84::toEcef(antennaReferencePoint());
}

Site surveyInSite(std::string name, const wgs84::Geodetic &antenna, std::optional<double> accuracyM,
                  std::string date) {
    Site s;
    s.name = std::move(name);
    s.latDeg = antenna.latDeg;
    s.lonDeg = antenna.lonDeg;
    s.height = antenna.height;
    s.accuracy = accuracyM;
    s.date = std::move(date);
    s.method = "survey-in";
    return s;
}

std::string nameProblem(std::string_view name) {
    if (name.empty()) return "a site's name cannot be empty";
    std::size_t count = 0;
    for (std::size_t at = 0; at < name.size();) {
        const long cp = nextCodePoint(name, at);
        if (cp < 0) return "a site's name must be UTF-8 text";
        if (isControl(cp)) return "a site's name cannot hold a control character";
        ++count;
    }
    if (count > kMaxNameLength)
        return "a site's name is at most " + std::to_string(kMaxNameLength) + " characters, got " +
               std::to_string(count);
    if (name.front() == ' ' || name.back() == ' ')
        return "a site's name cannot start or end with a space";
    return {};
}

std::string siteProblem(const Site &s) {
    if (auto why = nameProblem(s.name); !why.empty()) return "name: " + why;
    if (!std::isfinite(s.latDeg) || s.latDeg < -90 || s.latDeg > 90)
        return "lat: " + decimalText(s.latDeg) + " is not a latitude from -90 to 90 degrees";
    if (!std::isfinite(s.lonDeg) || s.lonDeg < -180 || s.lonDeg > 180)
        return "lon: " + decimalText(s.lonDeg) + " is not a longitude from -180 to 180 degrees";
    if (s.height && (!std::isfinite(*s.height) || std::abs(*s.height) > 100'000))
        return "height: " + decimalText(*s.height) +
               " is not metres above the ellipsoid (within 100 km)";
    if (!std::isfinite(s.antennaHeight) || std::abs(s.antennaHeight) > 1000)
        return "antenna_height: " + decimalText(s.antennaHeight) +
               " is not an antenna height (metres, within 1 km)";
    if (s.accuracy && (!std::isfinite(*s.accuracy) || *s.accuracy < 0))
        return "accuracy: " + decimalText(*s.accuracy) + " is not a distance in metres";
    if (!s.date.empty() && !isoDate(s.date))
        return "date: '" + s.date +
               "' is not an ISO 8601 date (2024-03-15 or 2024-03-15T10:00:00Z)";
    for (const std::string *text : {&s.method, &s.note}) {
        if (text->size() > 4096)
            return std::string(text == &s.method ? "method" : "note") + ": longer than 4096 bytes";
    }
    return {};
}

std::string foldedName(std::string_view name) {
    std::string out;
    out.reserve(name.size());
    for (std::size_t at = 0; at < name.size();) {
        const std::size_t start = at;
        const long cp = nextCodePoint(name, at);
        if (cp < 0)
            out.append(name.substr(start, at - start));
        else
            appendUtf8(out, lowerCodePoint(cp));
    }
    return out;
}

bool sameName(std::string_view a, std::string_view b) {
    return foldedName(a) == foldedName(b);
}

std::string todayUtc() {
    const std::time_t now = std::time(nullptr);
    std::tm t{};
    gmtime_r(&now, &t);
    char b[16];
    std::strftime(b, sizeof b, "%Y-%m-%d", &t);
    return b;
}

SiteList::AddResult SiteList::add(const Site &site, bool replace) {
    if (!siteProblem(site).empty()) return AddResult::Invalid;
    const std::string key = foldedName(site.name);
    const auto at = std::find_if(sites_.begin(), sites_.end(),
                                 [&](const Site &s) { return foldedName(s.name) == key; });
    if (at != sites_.end()) {
        if (!replace) return AddResult::Conflict;
        *at = site;
        std::sort(sites_.begin(), sites_.end(), siteNameLess);
        return AddResult::Replaced;
    }
    sites_.insert(std::upper_bound(sites_.begin(), sites_.end(), site, siteNameLess), site);
    return AddResult::Added;
}

bool SiteList::remove(std::string_view name) {
    const std::string key = foldedName(name);
    const auto at = std::find_if(sites_.begin(), sites_.end(),
                                 [&](const Site &s) { return foldedName(s.name) == key; });
    if (at == sites_.end()) return false;
    sites_.erase(at);
    return true;
}

const Site *SiteList::find(std::string_view name) const {
    const std::string key = foldedName(name);
    for (const Site &s : sites_)
        if (foldedName(s.name) == key) return &s;
    return nullptr;
}

SiteList::Lookup SiteList::lookup(std::string_view text) const {
    Lookup l;
    if (const Site *s = find(text)) {
        l.site = s;
        return l;
    }
    const std::string key = foldedName(text);
    std::vector<const Site *> starting;
    for (const Site &s : sites_)
        if (!key.empty() && foldedName(s.name).starts_with(key)) starting.push_back(&s);
    if (starting.size() == 1) {
        l.site = starting.front();
        return l;
    }
    if (starting.size() > 1) {
        l.ambiguous = true;
        for (const Site *s : starting) l.candidates.push_back(s->name);
        return l;
    }
    // Not found: names that hold the text, or begin as it does (its first three characters).
    const std::string head = key.substr(0, std::min<std::size_t>(key.size(), 3));
    for (const Site &s : sites_) {
        const std::string folded = foldedName(s.name);
        if (!key.empty() && (folded.find(key) != std::string::npos || folded.starts_with(head)))
            l.candidates.push_back(s.name);
        if (l.candidates.size() == 5) break;
    }
    return l;
}

SiteList::MergeReport SiteList::merge(const std::vector<Site> &incoming, bool replace) {
    MergeReport r;
    for (const Site &s : incoming) {
        switch (add(s, replace)) {
        case AddResult::Added: r.added.push_back(s.name); break;
        case AddResult::Replaced: r.replaced.push_back(s.name); break;
        case AddResult::Conflict: r.conflicts.push_back(s.name); break;
        case AddResult::Invalid: break; // checked when read
        }
    }
    return r;
}

} // namespace gnss::sites
