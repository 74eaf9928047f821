#include "cli/log_open.h"

#include "logview/log_range.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <unistd.h>

namespace gnss::cli {

OpenedLog::TempFile::~TempFile() {
    if (!path.empty()) ::unlink(path.c_str());
}

namespace {

// Standard input, whole, into a new temporary file; its path, or empty with `error` set.
std::string copyStandardInput(std::string &error) {
    const char *dir = std::getenv("TMPDIR");
    std::string path = std::string(dir && *dir ? dir : "/tmp") + "/gnss-cli-stdin-XXXXXX";
    const int fd = ::mkstemp(path.data());
    if (fd < 0) {
        error = "cannot make a temporary file for standard input in " + path + ": " +
                std::strerror(errno);
        return {};
    }
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
        if (n == 0) break;
        if (n < 0 && errno == EINTR) continue;
        bool written = n > 0;
        for (ssize_t done = 0; written && done < n;) {
            const ssize_t w = ::write(fd, buffer + done, static_cast<std::size_t>(n - done));
            if (w < 0 && errno == EINTR) continue;
            written = w > 0;
            done += w > 0 ? w : 0;
        }
        if (!written) {
            error = std::string(n < 0 ? "cannot read standard input: "
                                      : "cannot write the copy of standard input: ") +
                    std::strerror(errno);
            ::close(fd);
            ::unlink(path.c_str());
            return {};
        }
    }
    ::close(fd);
    return path;
}

} // namespace

int openLogForCommand(const CliContext &ctx, OpenedLog &out) {
    const Args &args = ctx.args;
    if (args.positionals().size() != 1) {
        std::fprintf(stderr, "gnss-cli: one log FILE, please\n");
        return 2;
    }
    out.path = args.positionals().front();
    std::string openPath = out.path;
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
    // The request is checked before standard input is read.
    if (out.path == "-") {
        std::string error;
        out.stdinCopy.path = copyStandardInput(error);
        if (out.stdinCopy.path.empty()) {
            std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());
            return 1;
        }
        openPath = out.stdinCopy.path;
    }
    out.view = std::make_unique<logview::LogView>(ctx.registry, options);
    out.view->open(openPath);
    const bool tty = ::isatty(STDERR_FILENO);
    while (!out.view->waitUntilIndexed(tty ? 200 : -1)) {
        const auto p = out.view->progress();
        std::fprintf(stderr, "\rgnss-cli: %s %s: %3.0f %%",
                     p.phase == logview::LogView::Phase::Inflating ? "inflating" : "indexing",
                     out.path.c_str(), p.fraction * 100);
    }
    if (tty) std::fprintf(stderr, "\r\033[K");
    // The engine's words name the file it opened: the copy of standard input is "standard input".
    auto said = [&out](std::string text) {
        const std::string &copy = out.stdinCopy.path;
        for (auto at = copy.empty() ? std::string::npos : text.find(copy); at != std::string::npos;
             at = text.find(copy, at))
            text.replace(at, copy.size(), "standard input");
        return text;
    };
    if (out.view->progress().phase != logview::LogView::Phase::Ready) {
        std::fprintf(stderr, "gnss-cli: %s\n", said(out.view->error()).c_str());
        return 1;
    }
    for (const std::string &w : out.view->warnings())
        std::fprintf(stderr, "gnss-cli: %s\n", said(w).c_str());
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
