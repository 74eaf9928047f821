#include "log_open.h"

#include <cstdio>
#include <thread>
#include <unistd.h>

namespace gnss::cli {

int openLogForCommand(const CliContext &ctx, OpenedLog &out) {
    const Args &args = ctx.args;
    if (args.positionals().size() != 1) {
        std::fprintf(stderr, "gnss-cli: one log FILE, please\n");
        return 2;
    }
    out.path = args.positionals().front();
    logview::LogViewOptions options;
    options.index.decoder.dialect = args.option("dialect").value_or("auto");
    if (options.index.decoder.dialect != "auto" &&
        !ctx.registry.find(options.index.decoder.dialect)) {
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s'\n",
                     options.index.decoder.dialect.c_str());
        return 2;
    }
    options.index.decoder.lenient = args.flag("lenient");
    std::optional<logview::TimeSpec> from, to;
    for (const char *name : {"from", "to"}) {
        if (const auto v = args.option(name)) {
            const auto t = logview::parseTimeSpec(*v);
            if (!t) {
                std::fprintf(stderr,
                             "gnss-cli: --%s takes a UTC time (2024-03-15T10:00:00Z), a time of "
                             "day (10:00:00) or an epoch number (#1200), not '%s'\n",
                             name, v->c_str());
                return 2;
            }
            (name[0] == 'f' ? from : to) = t;
        }
    }
    out.view = std::make_unique<logview::LogView>(ctx.registry, options);
    out.view->open(out.path);
    const bool tty = ::isatty(STDERR_FILENO);
    while (!out.view->waitUntilIndexed(tty ? 200 : -1)) {
        const auto p = out.view->progress();
        std::fprintf(stderr, "\rgnss-cli: %s %s: %3.0f %%",
                     p.phase == logview::LogView::Phase::Inflating ? "inflating" : "indexing",
                     out.path.c_str(), p.fraction * 100);
    }
    if (tty) std::fprintf(stderr, "\r\033[K");
    if (out.view->progress().phase != logview::LogView::Phase::Ready) {
        std::fprintf(stderr, "gnss-cli: %s\n", out.view->error().c_str());
        return 1;
    }
    for (const std::string &w : out.view->warnings())
        std::fprintf(stderr, "gnss-cli: %s\n", w.c_str());
    const std::size_t n = out.view->epochCount();
    out.first = 0;
    out.last = n == 0 ? 0 : n - 1;
    if (n == 0) {
        out.first = 1; // empty
        return 0;
    }
    if (from) {
        const auto k = out.view->epochAt(*from);
        if (!k) {
            out.first = n; // after the end: nothing
            out.last = n - 1;
            return 0;
        }
        out.first = *k;
    }
    if (to) {
        // The last epoch at or before `to`.
        logview::TimeSpec after = *to;
        if (after.kind == logview::TimeSpec::Kind::Epoch)
            ++after.epoch;
        else
            after.ms += 1;
        const auto k = out.view->epochAt(after);
        out.last = k ? (*k == 0 ? 0 : *k - 1) : n - 1;
        if (k && *k == 0) out.first = 1, out.last = 0;
    }
    return 0;
}

} // namespace gnss::cli
