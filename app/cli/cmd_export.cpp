// gnss-cli export: a log or a range of it as GPX, KML, CSV or its own NMEA bytes.
#include "cli/log_open.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace gnss::cli {

int cmdExport(const CliContext &ctx) {
    const auto formatName = ctx.args.option("format");
    if (!formatName) {
        std::fprintf(stderr, "gnss-cli: export needs --format gpx|kml|csv|nmea\n");
        return 2;
    }
    const auto format = logview::exportFormatFromName(*formatName);
    if (!format) {
        std::fprintf(stderr, "gnss-cli: --format takes gpx, kml, csv or nmea, not '%s'\n",
                     formatName->c_str());
        return 2;
    }
    const auto outPath = ctx.args.option("out");
    if (!outPath) {
        std::fprintf(stderr,
                     "gnss-cli: export needs -o OUT (or --out OUT; - for standard output)\n");
        return 2;
    }
    OpenedLog log;
    if (const int rc = openLogForCommand(ctx, log)) return rc;
    if (log.view->epochCount() == 0) {
        // Not NMEA, or no fix in it: said so (the warnings above), and no OUT written.
        std::fprintf(stderr, "gnss-cli: nothing to export, %s was not written\n", outPath->c_str());
        return 1;
    }
    const bool toStdout = *outPath == "-";
    std::FILE *f = toStdout ? stdout : std::fopen(outPath->c_str(), "wb");
    if (!f) {
        std::fprintf(stderr, "gnss-cli: %s: %s\n", outPath->c_str(), std::strerror(errno));
        return 1;
    }
    const logview::ExportSink sink = [f](std::string_view bytes) {
        return std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    };
    std::string name = log.path;
    if (const auto slash = name.rfind('/'); slash != std::string::npos) name.erase(0, slash + 1);
    bool ok = log.empty() ? log.view->exportRange(*format, 1, 0, sink, name)
                          : log.view->exportRange(*format, log.first, log.last, sink, name);
    if (std::fflush(f) != 0) ok = false;
    if (!toStdout && std::fclose(f) != 0) ok = false;
    if (!ok) {
        std::fprintf(stderr, "gnss-cli: cannot write %s: %s\n", outPath->c_str(),
                     std::strerror(errno));
        return 1;
    }
    std::fprintf(stderr, "gnss-cli: %zu epochs written to %s\n",
                 log.empty() ? std::size_t(0) : log.last - log.first + 1, outPath->c_str());
    return 0;
}

} // namespace gnss::cli
