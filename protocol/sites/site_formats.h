#pragma once
// The site list's files, in plain C++: JSON written ({"format": "gnss-workbench-sites",
// "version": 1, "sites": [...]}; read by site_store.h, with Qt's parser) and CSV written and read
// (RFC 4180; header name,lat,lon,height,antenna_height,accuracy,date,method,note).
#include "core/json_writer.h"
#include "sites/site.h"

#include <string>
#include <string_view>
#include <vector>

namespace gnss::sites {

inline constexpr std::string_view kJsonFormat = "gnss-workbench-sites";
inline constexpr int kJsonVersion = 1;
// The CSV columns, in the order written; name, lat and lon must be there when read.
inline constexpr std::string_view kCsvColumns[] = {
        "name", "lat", "lon", "height", "antenna_height", "accuracy", "date", "method", "note"};

// One site as a JSON object (optional values left out when unknown).
void writeSiteJson(JsonWriter &w, const Site &site);
// The versioned document, a line at the end.
std::string sitesToJson(const std::vector<Site> &sites);
// The header and a row per site, lines ending in CRLF as RFC 4180 has them.
std::string sitesToCsv(const std::vector<Site> &sites);

// What reading a file gave: its sites (in the file's order) or, when anything was wrong, the
// errors in words with their place ("line 4: lat: ...", "site 2 (\"Roof\"): field \"lat\": ...").
// A file with any error gives no site.
struct SitesRead {
    std::vector<Site> sites;
    std::vector<std::string> errors;
    bool ok() const { return errors.empty(); }
};
// CSV: columns in any order, named by the header (name, lat and lon required; an unknown column
// is an error); empty optional cells are unknown; a BOM and CRLF or LF line ends accepted; two
// sites of one name are an error.
SitesRead sitesFromCsv(std::string_view text);
// The checks a read file's sites share: each site (siteProblem) and no name twice. `where(i)`
// names the i-th site's place for the errors.
template <class Where> void checkSitesRead(SitesRead &read, Where where) {
    for (std::size_t i = 0; i < read.sites.size(); ++i) {
        if (auto why = siteProblem(read.sites[i]); !why.empty())
            read.errors.push_back(where(i) + ": " + why);
        for (std::size_t j = 0; j < i; ++j)
            if (sameName(read.sites[j].name, read.sites[i].name)) {
                read.errors.push_back(where(i) + ": the name '" + read.sites[i].name +
                                      "' is already used by " + where(j));
                break;
            }
    }
    if (!read.errors.empty()) read.sites.clear();
}

} // namespace gnss::sites
