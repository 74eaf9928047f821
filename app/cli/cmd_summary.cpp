// gnss-cli summary: what a log holds, in a few lines (or one JSON object).
#include "cli/log_open.h"
#include "cli/site_reference.h"
#include "compare/accuracy.h"
#include "core/json_writer.h"
#include "state/epoch.h"
#include "state/epochs_of_log.h"

#include <cstdio>

namespace gnss::cli {
namespace {

std::string timeText(const logview::RangeStats &s, const std::optional<std::int64_t> &ms) {
    if (!ms) return "-";
    logview::EpochRecord r;
    r.utcMs = *ms;
    if (s.dated) r.flags = logview::kDateKnown;
    return logview::formatTime(r);
}

std::string duration(double s) {
    char b[64];
    const long t = static_cast<long>(s);
    if (s >= 3600)
        std::snprintf(b, sizeof b, "%ld h %02ld min %02ld s", t / 3600, t / 60 % 60, t % 60);
    else if (s >= 60)
        std::snprintf(b, sizeof b, "%ld min %04.1f s", t / 60, s - 60.0 * (t / 60));
    else
        std::snprintf(b, sizeof b, "%.1f s", s);
    return b;
}

// The range's positions against the point, decoded again in full (the index keeps no
// ellipsoidal height).
compare::AccuracyReport accuracyOf(const CliContext &ctx, const OpenedLog &log,
                                   const compare::ReferencePoint &point) {
    compare::Accuracy accuracy(point);
    if (log.empty()) return accuracy.report();
    const logview::LogView::Slice slice = log.view->slice(log.first, log.last);
    epochsOfLog(slice.bytes, ctx.registry, slice.dialect, [&](const Epoch &e) { accuracy.add(e); });
    return accuracy.report();
}

std::string accuracyText(const compare::AccuracyReport &r, const compare::ReferencePoint &p) {
    char b[512];
    std::string o;
    auto line = [&](const char *fmt, auto... a) {
        std::snprintf(b, sizeof b, fmt, a...);
        o += b;
    };
    line("against %.8f, %.8f", p.latDeg, p.lonDeg);
    if (p.height) line(", %.3f m", *p.height);
    line(" (%zu positions):\n", r.positions);
    if (!r.positions) return o;
    line("  bias: east %.3f m, north %.3f m", r.biasEast, r.biasNorth);
    if (r.biasUp) line(", up %.3f m", *r.biasUp);
    o += "\n";
    line("  horizontal: mean %.3f m, median %.3f m, R95 %.3f m, 2DRMS %.3f m; CEP50 %.3f m, "
         "CEP95 %.3f m about the mean\n",
         r.horizontal.mean, r.horizontal.median, r.horizontal.p95, r.drms2, r.cep50, r.cep95);
    if (r.heights)
        line("  vertical: mean %.3f m, median %.3f m, 95 %% %.3f m\n", r.vertical.mean,
             r.vertical.median, r.vertical.p95);
    else if (p.height)
        o += "  vertical: no heights above the ellipsoid (no geoid separation given)\n";
    o += "  within";
    for (std::size_t k = 0; k < compare::kWithinMetres.size(); ++k)
        line("%s %g m %.1f %%", k ? "," : "", compare::kWithinMetres[k], r.within.percent[k]);
    o += "\n";
    return o;
}

} // namespace

int cmdSummary(const CliContext &ctx) {
    std::optional<compare::ReferencePoint> point;
    if (const int rc = referenceFromArgs(ctx.args, point)) return rc;
    OpenedLog log;
    if (const int rc = openLogForCommand(ctx, log)) return rc;
    logview::LogView &v = *log.view;
    const std::size_t first = log.first, last = log.last;
    const std::optional<compare::AccuracyReport> accuracy =
            point ? std::optional(accuracyOf(ctx, log, *point)) : std::nullopt;
    const logview::RangeStats all = v.stats(first, last);
    const logview::RangeStats still = v.stats(first, last, true);
    std::vector<logview::LogEvent> events;
    for (auto &e : v.events())
        if (!log.empty() && e.epoch >= first && e.epoch <= last) events.push_back(std::move(e));
    const FramerStats fs = v.framerStats();
    std::string o;
    if (ctx.args.flag("json")) {
        JsonWriter w(o);
        w.beginObject().field("file", log.path).field("bytes", v.fileSize());
        w.field("gzip", v.gzipped()).field("host_times", v.hasHostTimes());
        // No vendor sentence recognised: a standard NMEA receiver (--dialect nmea), not an
        // unknown one.
        w.field("dialect", v.dialectName().empty() ? std::string("nmea") : v.dialectName());
        w.field("sentences", fs.sentences).field("bytes_skipped", fs.bytesSkipped);
        w.field("lines_cut", fs.truncated + fs.tooLong + fs.binaryAborted);
        w.key("stats");
        all.writeJson(w);
        w.key("stationary");
        still.writeJson(w);
        w.key("events").beginArray();
        for (const auto &e : events) {
            logview::EpochRecord r;
            r.utcMs = e.utcMs;
            if (e.dated) r.flags = logview::kDateKnown;
            w.beginObject().field("epoch", e.epoch).field("time", logview::formatTime(r));
            w.field("kind", logview::toString(e.kind)).field("text", e.text).endObject();
        }
        w.endArray();
        if (accuracy) {
            w.key("reference");
            accuracy->writeJson(w, *point);
        }
        w.key("warnings").beginArray();
        for (const auto &x : v.warnings()) w.value(x);
        w.endArray().endObject();
        o += '\n';
    } else {
        char b[512];
        auto line = [&](const char *fmt, auto... a) {
            std::snprintf(b, sizeof b, fmt, a...);
            o += b;
        };
        line("file: %s (%.1f MB%s%s)\n", log.path.c_str(), v.fileSize() / 1e6,
             v.gzipped() ? ", gzip" : "", v.hasHostTimes() ? ", host times from .idx" : "");
        line("dialect: %s\n",
             v.dialectName().empty() ? "nmea (no vendor sentences)" : v.dialectName().c_str());
        line("sentences: %llu; junk: %llu bytes, %llu lines cut\n",
             static_cast<unsigned long long>(fs.sentences),
             static_cast<unsigned long long>(fs.bytesSkipped),
             static_cast<unsigned long long>(fs.truncated + fs.tooLong + fs.binaryAborted));
        line("epochs: %llu, %s to %s (%s)\n", static_cast<unsigned long long>(all.epochs),
             timeText(all, all.startMs).c_str(), timeText(all, all.endMs).c_str(),
             duration(all.durationS).c_str());
        o += "availability:";
        bool any = false;
        for (int f = static_cast<int>(FixType::Simulator); f >= 0; --f) {
            const auto fix = static_cast<FixType>(f);
            if (!all.perFix[f]) continue;
            line("%s %s %.1f %%", any ? "," : "", std::string(logview::fixWords(fix)).c_str(),
                 all.availability(fix));
            any = true;
        }
        o += any ? "\n" : " -\n";
        o += "time to first fix: " +
             (all.timeToFirstFixS ? duration(*all.timeToFirstFixS) : std::string("none")) +
             "; to RTK fixed: " +
             (all.timeToRtkFixedS ? duration(*all.timeToRtkFixedS) : std::string("none")) + "\n";
        line("gaps: %llu", static_cast<unsigned long long>(all.gaps));
        if (all.gaps) {
            const auto r = v.epoch(all.longestGapEpoch);
            line(", longest %s (before %s)", duration(all.longestGapS).c_str(),
                 r ? logview::formatTime(*r).c_str() : "?");
        }
        line("; time jumps: %llu; checksum errors: %llu\n",
             static_cast<unsigned long long>(all.timeJumps),
             static_cast<unsigned long long>(all.checksumErrors));
        if (still.cep50)
            line("CEP of the %s (%llu positions): CEP50 %.3f m, CEP95 %.3f m, 2DRMS %.3f m\n",
                 still.stationaryOnly ? "stationary part" : "positions",
                 static_cast<unsigned long long>(still.positions), *still.cep50, *still.cep95,
                 *still.drms2);
        else
            o += "CEP: no positions\n";
        if (all.maxHdop) line("max HDOP: %.2f\n", *all.maxHdop);
        if (accuracy) o += accuracyText(*accuracy, *point);
        line("events: %zu\n", events.size());
        for (const auto &e : events) {
            logview::EpochRecord r;
            r.utcMs = e.utcMs;
            if (e.dated) r.flags = logview::kDateKnown;
            line("  %-24s %-12s %s\n", logview::formatTime(r).c_str(),
                 std::string(logview::toString(e.kind)).c_str(), e.text.c_str());
        }
    }
    std::fwrite(o.data(), 1, o.size(), stdout);
    return 0;
}

} // namespace gnss::cli
