// gnss-cli compare: two receivers or more on the same sky, matched epoch by epoch on UTC time
// (protocol/compare). A source is a log file or a live one (--port, --tcp, --gpsd, --sim, each
// repeatable; ports at the speed baud detection finds), in the order given: the first is the
// reference, and every difference is another receiver minus it. Logs alone are compared at
// once; with a live source among them, logs are replayed at their own pace beside it.
#include "cli/cli_commands.h"
#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/event_loop.h"
#include "cli/input_reader.h"
#include "compare/comparison.h"
#include "compare/comparison_json.h"
#include "core/json_writer.h"
#include "core/stream_decoder.h"
#include "link/sentence_stream.h"
#include "link/transport.h"
#include "link/vendor_detector.h"
#include "state/epoch_assembler.h"

#include <QCoreApplication>
#include <QObject>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace gnss::cli {

namespace {

using Kind = link::SourceSpec::Kind;

struct Source {
    std::string file;                     // a log
    std::optional<link::SourceSpec> live; // or a live source
};

std::string dialectId(const Dialect *d) {
    return d ? std::string(d->id) : std::string("nmea");
}

// A log's epochs as observations; false (said on standard error) when it cannot be read.
bool readLog(const CliContext &ctx, const DecoderOptions &options, const std::string &path,
             std::vector<compare::Observation> &out, std::string &dialect) {
    StreamDecoder decoder(ctx.registry, options);
    EpochAssembler assembler(decoder.dialect());
    auto keep = [&](const Epoch &e) {
        if (auto o = compare::Observation::of(e)) out.push_back(std::move(*o));
    };
    std::string error;
    const bool ok = readInput(
            path,
            [&](std::string_view chunk) {
                decoder.feed(chunk, [&](const SentenceEvent &ev) {
                    if (!ev.message) return;
                    assembler.setDialect(decoder.dialect());
                    assembler.add(ev.sentence, *ev.message, keep);
                });
            },
            error);
    decoder.finish();
    assembler.flush(keep);
    dialect = dialectId(decoder.dialect());
    if (!ok) std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());
    return ok;
}

} // namespace

int cmdCompare(const CliContext &ctx) {
    const Args &args = ctx.args;
    double duration = 0;
    if (const auto d = args.option("duration")) {
        bool ok = false;
        duration = QString::fromStdString(*d).toDouble(&ok);
        if (!ok || duration < 0) {
            std::fprintf(stderr, "gnss-cli: --duration expects seconds >= 0, got '%s'\n",
                         d->c_str());
            return 2;
        }
    }
    DecoderOptions decoderOptions;
    decoderOptions.dialect = args.option("dialect").value_or("auto");
    decoderOptions.lenient = args.flag("lenient");
    if (decoderOptions.dialect != "auto" && !ctx.registry.find(decoderOptions.dialect)) {
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s'\n", decoderOptions.dialect.c_str());
        return 2;
    }
    std::vector<Source> sources;
    bool anyLive = false;
    for (const auto &[name, value] : args.inOrder()) {
        if (name.empty()) {
            sources.push_back({value, std::nullopt});
            continue;
        }
        const auto kind = sourceKindOf(name);
        if (!kind) continue; // --duration and the like
        std::string error;
        auto spec = sourceSpecOf(*kind, value, error);
        if (!spec) {
            std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());
            return 2;
        }
        sources.push_back({{}, spec});
        anyLive = true;
    }
    if (sources.size() < 2) {
        std::fprintf(stderr, "gnss-cli: compare needs two sources or more (a log FILE, --port, "
                             "--tcp, --gpsd or --sim; the first is the reference)\n");
        return 2;
    }
    if (!anyLive && duration > 0) {
        std::fprintf(stderr, "gnss-cli: --duration is for live sources; logs are compared whole\n");
        return 2;
    }
    std::vector<std::string> names;
    for (const Source &s : sources) names.push_back(s.live ? utf8(s.live->name) : s.file);
    compare::Comparison comparison(names);
    const bool json = args.flag("json");
    auto onMatch = [&](const compare::Match &m) {
        if (!json) printJson([&](JsonWriter &w) { compare::writeMatchJson(w, m, names); });
    };

    int rc = 0;
    if (!anyLive) {
        std::vector<std::vector<compare::Observation>> logs(sources.size());
        for (std::size_t i = 0; i < sources.size(); ++i) {
            std::string dialect;
            if (!readLog(ctx, decoderOptions, sources[i].file, logs[i], dialect)) return 1;
            comparison.setDialect(i, dialect);
        }
        comparison.addInTimeOrder(logs, onMatch);
    } else {
        EventLoop loop;
        std::vector<std::unique_ptr<link::Connection>> connections;
        std::vector<std::unique_ptr<EpochAssembler>> assemblers;
        std::vector<std::unique_ptr<link::VendorDetector>> detectors;
        std::vector<link::VendorIdentity> identities(sources.size());
        std::vector<link::SourceSpec> specs;
        for (const Source &src : sources)
            specs.push_back(
                    src.live ? *src.live
                             : link::SourceSpec{Kind::Replay, QString::fromStdString(src.file)});
        OpenOptions o;
        o.decoder = decoderOptions;
        o.waitUntilOpen = false; // nothing missed: listened to before it opens
        QString why;
        bool refused = false;
        // Every port's speed is looked for at once.
        auto opened = openConnections(ctx, specs, o, why, &refused);
        if (opened.empty()) {
            std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
            return refused ? 2 : 1;
        }
        for (std::size_t i = 0; i < sources.size(); ++i) {
            auto conn = std::move(opened[i]);
            if (specs[i].kind == Kind::Replay) conn->setAutoReconnect(false);
            reportLinkEvents(*conn, "");
            assemblers.push_back(std::make_unique<EpochAssembler>(conn->stream()->dialect()));
            EpochAssembler *assembler = assemblers.back().get();
            link::Connection *c = conn.get();
            QObject::connect(c->stream(), &link::SentenceStream::sentenceDecoded,
                             [&, i, c, assembler](const SentenceEvent &ev) {
                                 if (!ev.message) return;
                                 assembler->setDialect(c->stream()->dialect());
                                 assembler->add(ev.sentence, *ev.message, [&](const Epoch &e) {
                                     if (auto obs = compare::Observation::of(e))
                                         comparison.add(i, std::move(*obs), onMatch);
                                 });
                             });
            // Who is on the line (its model, for its name; its dialect, for its numbering), from
            // its output and, where it may be written to, its probe, as the window does.
            auto detector = std::make_unique<link::VendorDetector>(c->stream());
            detector->setActive(c->transport()->canWrite());
            QObject::connect(detector.get(), &link::VendorDetector::finished,
                             [&, i, c](const link::VendorIdentity &id) {
                                 identities[i] = id;
                                 if (const Dialect *d = ctx.registry.find(utf8(id.dialect)))
                                     c->stream()->setDialect(d);
                             });
            auto start = [d = detector.get()] { d->start(); };
            if (c->transport()->isOpen())
                start();
            else
                QObject::connect(c, &link::Connection::opened, detector.get(), start);
            detectors.push_back(std::move(detector));
            connections.push_back(std::move(conn));
        }
        loop.stopAfter(duration);
        rc = loop.exec();
        for (std::size_t i = 0; i < connections.size(); ++i) {
            const link::VendorIdentity &id = identities[i];
            const Dialect *d = connections[i]->stream()->dialect();
            comparison.setDialect(i, id.found ? utf8(id.dialect) : dialectId(d));
            // Named by the receiver found on the line (its model where it says it) and where.
            const std::string who = !id.model.isEmpty() ? utf8(id.model)
                                    : id.found          ? utf8(id.dialectName)
                                    : d                 ? std::string(d->displayName)
                                                        : std::string();
            const std::string where = utf8(connections[i]->transport()->description());
            if (!who.empty()) comparison.setName(i, who + " " + where);
        }
    }
    const compare::Report report = comparison.report();
    if (json) {
        printJson([&](JsonWriter &w) { compare::writeReportJson(w, report); });
    } else {
        std::fputs(compare::reportText(report).c_str(), stderr);
    }
    if (rc != 0) return rc; // interrupted, or a source that could not be opened
    if (report.matchedEpochs == 0) {
        std::fprintf(stderr, "gnss-cli: no epoch of one UTC time from every source: nothing "
                             "compared\n");
        return 1;
    }
    return 0;
}

} // namespace gnss::cli
