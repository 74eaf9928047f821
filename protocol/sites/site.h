#pragma once
// A site: a named position (a survey mark, a roof antenna, a base station's point) with its
// antenna height, accuracy, date and how it was obtained; the list of them the GUI and gnss-cli
// share (name rules, look-up by name or unique prefix, merging an import). Plain C++: the file
// formats are in site_formats.h, the user's file in site_store.h (Qt).
#include "core/wgs84.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::sites {

inline constexpr std::size_t kMaxNameLength = 64; // characters (UTF-8 code points)

struct Site {
    std::string name;
    double latDeg = 0, lonDeg = 0;  // WGS-84 degrees, positive north and east
    std::optional<double> height;   // of the mark, metres above the ellipsoid; none: unknown
    double antennaHeight = 0;       // metres from the mark up to the antenna reference point
    std::optional<double> accuracy; // metres (e.g. horizontal sigma); none: unknown
    std::string date;               // ISO 8601: "2024-03-15" or "2024-03-15T10:00:00Z"; or empty
    std::string method;             // "survey-in", "known", "imported", "ppp" or free text
    std::string note;

    // The antenna reference point: the mark with antennaHeight added along the ellipsoidal
    // normal (height + antennaHeight; the height taken as 0 when unknown).
    wgs84::Geodetic antennaReferencePoint() const;
    wgs84::Ecef antennaReferenceEcef() const;
};

// A survey-in result (a receiver's averaged antenna position) as a site: method "survey-in",
// antenna height 0 (the position is the antenna's), the date as given.
Site surveyInSite(std::string name, const wgs84::Geodetic &antenna, std::optional<double> accuracyM,
                  std::string date);

// Why `name` cannot name a site (empty, longer than kMaxNameLength characters, a control
// character, not UTF-8, spaces at either end); empty when it can.
std::string nameProblem(std::string_view name);
// The first thing wrong with the site, naming the field ("lat: 91 is not from -90 to 90"); empty
// when nothing is.
std::string siteProblem(const Site &site);
// Names compare case-insensitively (ASCII, Latin-1 and Cyrillic letters fold to lower case).
std::string foldedName(std::string_view name);
bool sameName(std::string_view a, std::string_view b);
// A number as the shortest text that reads back the same, with a decimal point whatever the
// locale; and such text (or any decimal, "1e3") read back: false unless it is all a finite number.
std::string decimalText(double v);
bool parseDecimal(std::string_view text, double &out);
// Today's date, UTC, as "YYYY-MM-DD".
std::string todayUtc();

class SiteList {
public:
    enum class AddResult { Added, Replaced, Conflict, Invalid };
    // Adds the site; one of the same name (case-insensitively) is replaced only when `replace`,
    // else it is a Conflict and nothing changes. Invalid (siteProblem) changes nothing either.
    AddResult add(const Site &site, bool replace = false);
    bool remove(std::string_view name);            // by name, case-insensitively; false: none such
    const Site *find(std::string_view name) const; // by name, case-insensitively

    // By name, or by a case-insensitive prefix only one site's name starts with.
    struct Lookup {
        const Site *site = nullptr;          // found
        bool ambiguous = false;              // several names start with the text: `candidates`
        std::vector<std::string> candidates; // ambiguous: those; not found: close names
    };
    Lookup lookup(std::string_view text) const;

    // Every site, sorted by folded name.
    const std::vector<Site> &sites() const { return sites_; }
    std::size_t size() const { return sites_.size(); }
    bool empty() const { return sites_.empty(); }

    // What merging another list did: names added, replaced, and in conflict (kept as they were).
    struct MergeReport {
        std::vector<std::string> added, replaced, conflicts;
    };
    MergeReport merge(const std::vector<Site> &incoming, bool replace);

private:
    std::vector<Site> sites_;
};

} // namespace gnss::sites
