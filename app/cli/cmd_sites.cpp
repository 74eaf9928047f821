// gnss-cli sites: the user's list of named positions (protocol/sites), the one the GUI keeps:
// list, add, remove, export and import; and --reference-site for summary and ttff
// (site_reference.h).
#include "cli/cli_commands.h"
#include "cli/site_reference.h"
#include "core/json_writer.h"
#include "sites/site_store.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace gnss::cli {
namespace {

using sites::Site;
using sites::SiteList;
using sites::SiteStore;

void sitesSay(const std::string &text) {
    std::fprintf(stderr, "gnss-cli: sites: %s\n", text.c_str());
}

// 'A', 'B' and 'C'.
std::string quotedNames(const std::vector<std::string> &names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i) out += i + 1 == names.size() ? " and " : ", ";
        out += "'" + names[i] + "'";
    }
    return out;
}

// Why `text` names no one site of `list` (ambiguous or unknown, with the close names).
std::string notOneSite(const SiteList &list, const std::string &text,
                       const SiteList::Lookup &found) {
    if (found.ambiguous)
        return "'" + text + "' is ambiguous: it begins " + quotedNames(found.candidates);
    std::string why = "no site '" + text + "'";
    if (!found.candidates.empty())
        why += " (close: " + quotedNames(found.candidates) + ")";
    else if (list.empty())
        why += " (the list is empty: gnss-cli sites add NAME --llh LAT,LON[,HEIGHT])";
    return why;
}

bool loadSites(const SiteStore &store, SiteList &list) {
    QString error;
    if (store.load(list, error)) return true;
    sitesSay(error.toStdString());
    return false;
}

bool saveSites(const SiteStore &store, const SiteList &list) {
    QString error;
    if (store.save(list, error)) return true;
    sitesSay(error.toStdString());
    return false;
}

// The options each action takes; any other given is a usage error.
bool onlyOptions(const Args &args, std::string_view action,
                 std::initializer_list<std::string_view> allowed) {
    constexpr std::string_view kAll[] = {"json",   "llh",  "ecef", "antenna-height", "accuracy",
                                         "method", "note", "date", "replace"};
    for (const std::string_view o : kAll) {
        if (std::find(allowed.begin(), allowed.end(), o) != allowed.end()) continue;
        if (args.flag(o) || args.option(o)) {
            sitesSay("--" + std::string(o) + " is not an option of sites " + std::string(action));
            return false;
        }
    }
    return true;
}

bool metres(const Args &args, std::string_view name, std::optional<double> &out) {
    const auto text = args.option(name);
    if (!text) return true;
    double v = 0;
    if (!sites::parseDecimal(*text, v)) {
        sitesSay("--" + std::string(name) + " expects metres, got '" + *text + "'");
        return false;
    }
    out = v;
    return true;
}

// The site `sites add` describes, or none (said why).
std::optional<Site> siteFromArgs(const Args &args, const std::string &name) {
    Site s;
    s.name = name;
    const auto llh = args.option("llh"), ecef = args.option("ecef");
    if (llh.has_value() == ecef.has_value()) {
        sitesSay("add needs --llh LAT,LON[,HEIGHT] or --ecef X,Y,Z (one of them)");
        return std::nullopt;
    }
    if (llh) {
        std::string why;
        const auto p = compare::ReferencePoint::parse(*llh, why);
        if (!p) {
            sitesSay("--llh: " + why);
            return std::nullopt;
        }
        s.latDeg = p->latDeg;
        s.lonDeg = p->lonDeg;
        s.height = p->height;
    } else {
        double xyz[3];
        std::size_t n = 0, at = 0;
        for (; n < 3 && at <= ecef->size(); ++n) {
            const std::size_t comma = std::min(ecef->find(',', at), ecef->size());
            if (!sites::parseDecimal(std::string_view(*ecef).substr(at, comma - at), xyz[n])) break;
            at = comma + 1;
        }
        const auto g = n == 3 && at == ecef->size() + 1
                               ? wgs84::toGeodetic({xyz[0], xyz[1], xyz[2]})
                               : std::nullopt;
        if (!g) {
            sitesSay("--ecef expects X,Y,Z in metres (Earth-centred, Earth-fixed), got '" + *ecef +
                     "'");
            return std::nullopt;
        }
        s.latDeg = g->latDeg;
        s.lonDeg = g->lonDeg;
        s.height = g->height;
    }
    std::optional<double> antenna;
    if (!metres(args, "antenna-height", antenna) || !metres(args, "accuracy", s.accuracy))
        return std::nullopt;
    s.antennaHeight = antenna.value_or(0.0);
    s.date = args.option("date").value_or(sites::todayUtc());
    s.method = args.option("method").value_or("known");
    s.note = args.option("note").value_or("");
    if (const std::string why = sites::siteProblem(s); !why.empty()) {
        sitesSay(why);
        return std::nullopt;
    }
    return s;
}

// Characters (UTF-8 code points, not bytes).
std::size_t charCount(const std::string &text) {
    std::size_t chars = 0;
    for (const char c : text) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return chars;
}

std::string padded(const std::string &text, std::size_t width) {
    const std::size_t chars = charCount(text);
    return text + std::string(chars < width ? width - chars : 0, ' ');
}

std::string listText(const SiteList &list) {
    std::size_t width = 4;
    for (const Site &s : list.sites()) width = std::max(width, charCount(s.name));
    std::string o = padded("NAME", width) +
                    "  LAT            LON             HEIGHT     ANTENNA  ACCURACY  DATE        "
                    "METHOD\n";
    char b[160];
    for (const Site &s : list.sites()) {
        const std::string height =
                s.height ? (std::snprintf(b, sizeof b, "%.3f", *s.height), b) : std::string("-");
        const std::string accuracy = s.accuracy
                                             ? (std::snprintf(b, sizeof b, "%.3f", *s.accuracy), b)
                                             : std::string("-");
        std::snprintf(b, sizeof b, "  %-13.9f  %-14.9f  %-9s  %-7.3f  %-8s  %-10s  %s\n", s.latDeg,
                      s.lonDeg, height.c_str(), s.antennaHeight, accuracy.c_str(),
                      s.date.substr(0, 10).c_str(), s.method.c_str());
        o += padded(s.name, width) + b;
    }
    if (list.empty()) o = "no sites (gnss-cli sites add NAME --llh LAT,LON[,HEIGHT])\n";
    return o;
}

int sitesList(const Args &args, const SiteStore &store) {
    if (!onlyOptions(args, "list", {"json"})) return 2;
    SiteList list;
    if (!loadSites(store, list)) return 1;
    const std::string o = args.flag("json") ? sites::sitesToJson(list.sites()) : listText(list);
    std::fwrite(o.data(), 1, o.size(), stdout);
    return 0;
}

int sitesAdd(const Args &args, const SiteStore &store, const std::string &name) {
    if (!onlyOptions(
                args, "add",
                {"llh", "ecef", "antenna-height", "accuracy", "method", "note", "date", "replace"}))
        return 2;
    if (const std::string why = sites::nameProblem(name); !why.empty()) {
        sitesSay(why);
        return 2;
    }
    const std::optional<Site> site = siteFromArgs(args, name);
    if (!site) return 2;
    SiteList list;
    if (!loadSites(store, list)) return 1;
    const SiteList::AddResult r = list.add(*site, args.flag("replace"));
    if (r == SiteList::AddResult::Conflict) {
        sitesSay("a site named '" + list.find(name)->name +
                 "' is already in the list (--replace replaces it)");
        return 1;
    }
    if (!saveSites(store, list)) return 1;
    sitesSay((r == SiteList::AddResult::Replaced ? "replaced '" : "added '") + name + "' in " +
             store.filePath().toStdString());
    return 0;
}

int sitesRemove(const Args &args, const SiteStore &store, const std::string &name) {
    if (!onlyOptions(args, "remove", {})) return 2;
    SiteList list;
    if (!loadSites(store, list)) return 1;
    if (!list.find(name)) {
        const SiteList::Lookup found = list.lookup(name);
        // A prefix is enough to use a site, never to remove one: name it in full.
        sitesSay(found.site ? "no site '" + name + "' (did you mean '" + found.site->name + "'?)"
                            : notOneSite(list, name, found));
        return 2;
    }
    const std::string removed = list.find(name)->name;
    list.remove(name);
    if (!saveSites(store, list)) return 1;
    sitesSay("removed '" + removed + "'");
    return 0;
}

bool siteFileName(const std::string &file) {
    const QString suffix = QString::fromStdString(file).section('.', -1).toLower();
    if (suffix == "csv" || suffix == "json") return true;
    sitesSay("'" + file + "': a site file is FILE.csv or FILE.json");
    return false;
}

int sitesExport(const Args &args, const SiteStore &store, const std::string &file) {
    if (!onlyOptions(args, "export", {}) || !siteFileName(file)) return 2;
    SiteList list;
    if (!loadSites(store, list)) return 1;
    QString error;
    if (!SiteStore::writeFile(QString::fromStdString(file), list.sites(), error)) {
        sitesSay(error.toStdString());
        return 1;
    }
    sitesSay("wrote " + std::to_string(list.size()) + " sites to " + file);
    return 0;
}

int sitesImport(const Args &args, const SiteStore &store, const std::string &file) {
    if (!onlyOptions(args, "import", {"replace"}) || !siteFileName(file)) return 2;
    QString ioError;
    sites::SitesRead read = SiteStore::readFile(QString::fromStdString(file), ioError);
    if (!ioError.isEmpty()) {
        sitesSay(ioError.toStdString());
        return 1;
    }
    if (!read.ok()) {
        constexpr std::size_t kShown = 20;
        for (std::size_t i = 0; i < read.errors.size() && i < kShown; ++i)
            std::fprintf(stderr, "gnss-cli: %s: %s\n", file.c_str(), read.errors[i].c_str());
        if (read.errors.size() > kShown)
            std::fprintf(stderr, "gnss-cli: %s: and %zu more errors\n", file.c_str(),
                         read.errors.size() - kShown);
        sitesSay("nothing imported");
        return 2;
    }
    for (Site &s : read.sites)
        if (s.method.empty()) s.method = "imported";
    SiteList list;
    if (!loadSites(store, list)) return 1;
    const SiteList::MergeReport r = list.merge(read.sites, args.flag("replace"));
    if ((!r.added.empty() || !r.replaced.empty()) && !saveSites(store, list)) return 1;
    sitesSay("imported " + std::to_string(r.added.size()) + " new, replaced " +
             std::to_string(r.replaced.size()) + " from " + file);
    if (r.conflicts.empty()) return 0;
    sitesSay("kept " + std::to_string(r.conflicts.size()) +
             " already in the list: " + quotedNames(r.conflicts) + " (--replace replaces them)");
    return 1;
}

} // namespace

int cmdSites(const CliContext &ctx) {
    const Args &args = ctx.args;
    const auto &pos = args.positionals();
    const std::string action = pos.empty() ? std::string() : pos[0];
    const bool list = action == "list";
    const std::size_t wanted = list ? 1 : 2;
    if (!list && action != "add" && action != "remove" && action != "export" &&
        action != "import") {
        sitesSay(action.empty()
                         ? "expected list, add, remove, export or import"
                         : "unknown action '" + action + "' (list, add, remove, export, import)");
        return 2;
    }
    if (pos.size() != wanted) {
        sitesSay(pos.size() < wanted
                         ? action + " needs " +
                                   (action == "add" || action == "remove" ? "a NAME" : "a FILE")
                         : "unexpected '" + pos[wanted] + "' after sites " + action);
        return 2;
    }
    const SiteStore store;
    if (list) return sitesList(args, store);
    if (action == "add") return sitesAdd(args, store, pos[1]);
    if (action == "remove") return sitesRemove(args, store, pos[1]);
    if (action == "export") return sitesExport(args, store, pos[1]);
    return sitesImport(args, store, pos[1]);
}

int referenceFromArgs(const Args &args, std::optional<compare::ReferencePoint> &point) {
    const auto text = args.option("reference"), name = args.option("reference-site");
    if (text && name) {
        std::fprintf(stderr, "gnss-cli: --reference and --reference-site: give one of them\n");
        return 2;
    }
    if (text) {
        std::string why;
        point = compare::ReferencePoint::parse(*text, why);
        if (point) return 0;
        std::fprintf(stderr, "gnss-cli: --reference: %s\n", why.c_str());
        return 2;
    }
    if (!name) return 0;
    const SiteStore store;
    SiteList list;
    QString error;
    if (!store.load(list, error)) {
        std::fprintf(stderr, "gnss-cli: --reference-site: %s\n", error.toStdString().c_str());
        return 1;
    }
    const SiteList::Lookup found = list.lookup(*name);
    if (!found.site) {
        std::fprintf(stderr, "gnss-cli: --reference-site: %s\n",
                     notOneSite(list, *name, found).c_str());
        return 2;
    }
    // The receiver reports its antenna's position: the mark's height plus the antenna height.
    const wgs84::Geodetic arp = found.site->antennaReferencePoint();
    point = compare::ReferencePoint{arp.latDeg, arp.lonDeg,
                                    found.site->height ? std::optional(arp.height) : std::nullopt};
    return 0;
}

} // namespace gnss::cli
