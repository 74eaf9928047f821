// The site list's files: JSON written, CSV written and read (site_formats.h).
#include "sites/site_formats.h"

#include <algorithm>
#include <array>

namespace gnss::sites {
namespace {

// A CSV cell, quoted when it holds a comma, a quote, a line end or spaces at either end.
void appendCsvCell(std::string &out, std::string_view cell) {
    const bool quote = cell.find_first_of(",\"\r\n") != std::string_view::npos ||
                       (!cell.empty() && (cell.front() == ' ' || cell.back() == ' '));
    if (!quote) {
        out += cell;
        return;
    }
    out += '"';
    for (const char c : cell) {
        if (c == '"') out += '"';
        out += c;
    }
    out += '"';
}

std::string optionalText(const std::optional<double> &v) {
    return v ? decimalText(*v) : std::string();
}

struct CsvRecord {
    std::size_t line = 0; // where it starts, from 1
    std::vector<std::string> cells;
};

// RFC 4180 records; a quote left open is an error at the line it opened on.
std::vector<CsvRecord> csvRecords(std::string_view text, std::vector<std::string> &errors) {
    std::vector<CsvRecord> records;
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    std::size_t line = 1, at = 0;
    while (at < text.size()) {
        CsvRecord r;
        r.line = line;
        std::string cell;
        bool inQuotes = false, quoted = false, endOfRecord = false;
        std::size_t quoteLine = line;
        while (at < text.size() && !endOfRecord) {
            const char c = text[at++];
            if (inQuotes) {
                if (c == '"') {
                    if (at < text.size() && text[at] == '"') {
                        cell += '"';
                        ++at;
                    } else {
                        inQuotes = false;
                    }
                } else {
                    if (c == '\n') ++line;
                    cell += c;
                }
            } else if (c == '"' && cell.empty() && !quoted) {
                inQuotes = quoted = true;
                quoteLine = line;
            } else if (c == ',') {
                r.cells.push_back(std::move(cell));
                cell.clear();
                quoted = false;
            } else if (c == '\n' || c == '\r') {
                if (c == '\r' && at < text.size() && text[at] == '\n') ++at;
                ++line;
                endOfRecord = true;
            } else if (quoted) {
                errors.push_back("line " + std::to_string(line) +
                                 ": text after a quoted cell's closing quote");
                return {};
            } else {
                cell += c;
            }
        }
        if (inQuotes) {
            errors.push_back("line " + std::to_string(quoteLine) + ": a quote is never closed");
            return {};
        }
        r.cells.push_back(std::move(cell));
        const bool blank = r.cells.size() == 1 && r.cells.front().empty() && !quoted;
        if (!blank) records.push_back(std::move(r));
    }
    return records;
}

// A number cell into `out`; an empty optional cell leaves it unknown.
bool readNumberCell(const std::string &cell, std::optional<double> &out) {
    if (cell.empty()) return true;
    double v = 0;
    if (!parseDecimal(cell, v)) return false;
    out = v;
    return true;
}

} // namespace

void writeSiteJson(JsonWriter &w, const Site &s) {
    w.beginObject().field("name", s.name).field("lat", s.latDeg).field("lon", s.lonDeg);
    if (s.height) w.field("height", *s.height);
    w.field("antenna_height", s.antennaHeight);
    if (s.accuracy) w.field("accuracy", *s.accuracy);
    if (!s.date.empty()) w.field("date", s.date);
    if (!s.method.empty()) w.field("method", s.method);
    if (!s.note.empty()) w.field("note", s.note);
    w.endObject();
}

std::string sitesToJson(const std::vector<Site> &sites) {
    std::string out;
    JsonWriter w(out);
    w.beginObject().field("format", kJsonFormat).field("version", kJsonVersion);
    w.key("sites").beginArray();
    for (const Site &s : sites) writeSiteJson(w, s);
    w.endArray().endObject();
    out += '\n';
    return out;
}

std::string sitesToCsv(const std::vector<Site> &sites) {
    std::string out;
    for (std::size_t i = 0; i < std::size(kCsvColumns); ++i) {
        if (i) out += ',';
        out += kCsvColumns[i];
    }
    out += "\r\n";
    for (const Site &s : sites) {
        const std::array<std::string, std::size(kCsvColumns)> cells{s.name,
                                                                    decimalText(s.latDeg),
                                                                    decimalText(s.lonDeg),
                                                                    optionalText(s.height),
                                                                    decimalText(s.antennaHeight),
                                                                    optionalText(s.accuracy),
                                                                    s.date,
                                                                    s.method,
                                                                    s.note};
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i) out += ',';
            appendCsvCell(out, cells[i]);
        }
        out += "\r\n";
    }
    return out;
}

SitesRead sitesFromCsv(std::string_view text) {
    SitesRead read;
    const std::vector<CsvRecord> records = csvRecords(text, read.errors);
    if (!read.errors.empty()) return read;
    if (records.empty()) {
        read.errors.push_back("line 1: no header (expected name,lat,lon,...)");
        return read;
    }
    // Each known column's place in the file, or npos.
    constexpr std::size_t kNone = std::string::npos;
    std::array<std::size_t, std::size(kCsvColumns)> place;
    place.fill(kNone);
    const CsvRecord &header = records.front();
    for (std::size_t c = 0; c < header.cells.size(); ++c) {
        std::string name = header.cells[c];
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char ch) { return ch >= 'A' && ch <= 'Z' ? ch + 32 : ch; });
        const auto *known = std::find(std::begin(kCsvColumns), std::end(kCsvColumns), name);
        const std::string where = "line " + std::to_string(header.line) + ": column " +
                                  std::to_string(c + 1) + " '" + header.cells[c] + "'";
        if (known == std::end(kCsvColumns))
            read.errors.push_back(where + " is not one of name,lat,lon,height,antenna_height,"
                                          "accuracy,date,method,note");
        else if (place[known - std::begin(kCsvColumns)] != kNone)
            read.errors.push_back(where + " is given twice");
        else
            place[known - std::begin(kCsvColumns)] = c;
    }
    for (std::size_t k = 0; k < 3; ++k)
        if (place[k] == kNone)
            read.errors.push_back("line " + std::to_string(header.line) + ": no '" +
                                  std::string(kCsvColumns[k]) + "' column");
    if (!read.errors.empty()) return read;

    std::vector<std::size_t> lines;
    for (std::size_t r = 1; r < records.size(); ++r) {
        const CsvRecord &rec = records[r];
        const std::string where = "line " + std::to_string(rec.line);
        if (rec.cells.size() != header.cells.size()) {
            read.errors.push_back(where + ": " + std::to_string(rec.cells.size()) +
                                  " cells where the header has " +
                                  std::to_string(header.cells.size()));
            continue;
        }
        auto cell = [&](std::size_t k) -> const std::string & {
            static const std::string kEmpty;
            return place[k] == kNone ? kEmpty : rec.cells[place[k]];
        };
        Site s;
        s.name = cell(0);
        std::optional<double> lat, lon, antenna;
        const std::pair<std::size_t, std::optional<double> *> numbers[] = {
                {1, &lat}, {2, &lon}, {3, &s.height}, {4, &antenna}, {5, &s.accuracy}};
        bool ok = true;
        for (const auto &[k, target] : numbers) {
            if (!readNumberCell(cell(k), *target)) {
                read.errors.push_back(where + ": " + std::string(kCsvColumns[k]) + ": '" + cell(k) +
                                      "' is not a number (decimal point '.')");
                ok = false;
                break;
            }
        }
        if (ok && (!lat || !lon)) {
            read.errors.push_back(where + ": " + (lat ? "lon" : "lat") + " is empty");
            ok = false;
        }
        if (!ok) continue;
        s.latDeg = *lat;
        s.lonDeg = *lon;
        s.antennaHeight = antenna.value_or(0.0);
        s.date = cell(6);
        s.method = cell(7);
        s.note = cell(8);
        read.sites.push_back(std::move(s));
        lines.push_back(rec.line);
    }
    if (!read.errors.empty()) {
        read.sites.clear();
        return read;
    }
    checkSitesRead(read, [&](std::size_t i) { return "line " + std::to_string(lines[i]); });
    return read;
}

} // namespace gnss::sites
