#include "cli/log_open.h"

#include "logview/log_range.h"

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
    const logview::EpochRange range = logview::resolveRange(*out.view, from, to);
    const std::string fromText = args.option("from").value_or(""),
                      toText = args.option("to").value_or("");
    const std::string span = logview::logSpanText(*out.view);
    using Refusal = logview::EpochRange::Refusal;
    switch (range.refusal) {
    case Refusal::None: break;
    case Refusal::FromAfterEnd:
        std::fprintf(stderr, "gnss-cli: --from %s is after the log's end: the log runs from %s\n",
                     fromText.c_str(), span.c_str());
        return 2;
    case Refusal::ToBeforeStart:
        std::fprintf(stderr, "gnss-cli: --to %s is before the log's start: the log runs from %s\n",
                     toText.c_str(), span.c_str());
        return 2;
    case Refusal::Empty:
        std::fprintf(stderr,
                     "gnss-cli: --from %s is after --to %s: no epoch between them (the log runs "
                     "from %s)\n",
                     fromText.c_str(), toText.c_str(), span.c_str());
        return 2;
    case Refusal::Untimed: {
        // A whole UTC time in a log whose epochs have a time of day but no date, or any time in
        // a log whose epochs carry none.
        const bool anyTime =
                logview::lookUpTime(*out.view,
                                    logview::TimeSpec{logview::TimeSpec::Kind::TimeOfDay})
                        .place != logview::TimePlace::Untimed;
        std::fprintf(stderr, "gnss-cli: the log's epochs carry no %s: give %s\n",
                     anyTime ? "date" : "time",
                     anyTime ? "a time of day (10:00:00) or an epoch number (#1200)"
                             : "an epoch number (#1200)");
        return 2;
    }
    case Refusal::NoEpochs:
        std::fprintf(stderr, "gnss-cli: %s has no epochs: --from and --to have nothing to cut\n",
                     out.path.c_str());
        return 2;
    }
    if (range.cutStart)
        std::fprintf(stderr,
                     "gnss-cli: --from %s is before the log's start: from its first epoch, %s\n",
                     fromText.c_str(), logview::epochText(*out.view, range.first).c_str());
    if (range.cutEnd)
        std::fprintf(stderr, "gnss-cli: --to %s is after the log's end: to its last epoch, %s\n",
                     toText.c_str(), logview::epochText(*out.view, range.last).c_str());
    out.first = range.first;
    out.last = range.last;
    return 0;
}

} // namespace gnss::cli
