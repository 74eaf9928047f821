// gnss-cli ports | probe | monitor | record | send: the link layer (protocol/link) from the
// command line. These commands need Qt's event loop, so each creates its QCoreApplication; the
// file-based commands (decode, epochs, ...) stay Qt-free.
// Before any Qt header: it has a member named emit, which Qt defines as a macro.
#include "state/epoch_assembler.h"

#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/event_loop.h"
#include "core/json_writer.h"
#include "core/sentence_builder.h"
#include "link/baud_detector.h"
#include "link/connection.h"
#include "link/port_watcher.h"
#include "link/recording_name.h"
#include "link/replay_transport.h"
#include "link/sentence_stream.h"
#include "link/vendor_detector.h"

#include <QCoreApplication>
#include <QDir>
#include <QTimer>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

namespace gnss::cli {
namespace {

bool numberOption(const Args &args, const char *name, double &out) {
    const auto v = args.option(name);
    if (!v) return true;
    bool ok = false;
    out = QString::fromStdString(*v).toDouble(&ok);
    if (!ok || out < 0) {
        std::fprintf(stderr, "gnss-cli: --%s expects a number >= 0, got '%s'\n", name, v->c_str());
        return false;
    }
    return true;
}

using Kind = link::SourceSpec::Kind;

// One source the command was given, opened, and what it was called on the command line.
struct Opened {
    std::unique_ptr<link::Connection> connection;
    std::string source; // as given: the port, HOST:PORT, the file, the dialect simulated
};

// Opens `spec` (saying why on standard error when it cannot: rc 1, or 2 for a request refused).
std::unique_ptr<link::Connection> openSpec(const CliContext &ctx, const link::SourceSpec &spec,
                                           const OpenOptions &options, int &rc) {
    // A log that cannot be replayed (missing, or an index that contradicts it) stays so: it is
    // not retried, the command ends saying why.
    OpenOptions o = options;
    if (spec.kind == Kind::Replay) o.autoReconnect = false;
    QString why;
    bool refused = false;
    auto conn = openConnection(ctx, spec, o, why, &refused);
    if (!conn) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
        rc = refused ? 2 : 1;
    }
    return conn;
}

// The command's source from its arguments, opened (nullptr after saying why on standard error).
std::unique_ptr<link::Connection> open(const CliContext &ctx, const Args &args,
                                       std::initializer_list<Kind> allowed,
                                       const OpenOptions &options, int &rc) {
    std::string error;
    const auto spec = sourceFromArgs(args, allowed, error);
    if (!spec) {
        std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());
        rc = 2;
        return nullptr;
    }
    return openSpec(ctx, *spec, options, rc);
}

// How many sources the arguments give (each source option may be repeated).
std::size_t sourceCount(const Args &args) {
    std::size_t n = 0;
    for (const auto &[name, value] : args.inOrder()) n += !name.empty() && sourceKindOf(name);
    return n;
}

// Every source the arguments give, in their order, opened; empty after saying why (rc set).
std::vector<Opened> openAll(const CliContext &ctx, const Args &args,
                            std::initializer_list<Kind> allowed, const OpenOptions &options,
                            int &rc) {
    std::vector<link::SourceSpec> specs;
    std::vector<std::string> given;
    for (const auto &[name, value] : args.inOrder()) {
        const auto kind = name.empty() ? std::nullopt : sourceKindOf(name);
        if (!kind) continue;
        std::string error;
        auto spec = std::find(allowed.begin(), allowed.end(), *kind) == allowed.end()
                            ? std::nullopt
                            : sourceSpecOf(*kind, value, error);
        if (!spec) {
            std::fprintf(stderr, "gnss-cli: %s\n",
                         error.empty() ? ("this command does not take --" + name).c_str()
                                       : error.c_str());
            rc = 2;
            return {};
        }
        if (const auto b = args.option("baud")) {
            // As one source's --baud is checked (cli_source.cpp): a speed, or a usage error.
            spec->baud = std::atoi(b->c_str());
            if (spec->baud < 300 || spec->baud > 4000000) {
                std::fprintf(stderr,
                             "gnss-cli: --baud expects a speed such as 9600 or 115200, "
                             "got '%s'\n",
                             b->c_str());
                rc = 2;
                return {};
            }
        }
        specs.push_back(*spec);
        given.push_back(*kind == Kind::Simulator ? "sim " + value : value);
    }
    QString why;
    bool refused = false;
    auto connections = openConnections(ctx, specs, options, why, &refused);
    if (connections.empty()) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
        rc = refused ? 2 : 1;
        return {};
    }
    std::vector<Opened> out;
    for (std::size_t i = 0; i < specs.size(); ++i) {
        // A log that cannot be replayed stays so: not retried.
        if (specs[i].kind == Kind::Replay) connections[i]->setAutoReconnect(false);
        out.push_back({std::move(connections[i]), given[i]});
    }
    return out;
}

// `json` (one object) with "receiver" (its place among the sources) and "source" first.
std::string tagged(const std::string &json, std::size_t receiver, const std::string &source) {
    std::string head;
    JsonWriter w(head);
    // Left open: the object goes on with `json`'s own fields.
    w.beginObject().field("receiver", static_cast<std::uint64_t>(receiver)).field("source", source);
    return head + "," + json.substr(1);
}

// A file name for what `source` names ("/dev/ttyUSB0" -> "ttyUSB0.nmea"), unique in `taken`.
std::string fileNameFor(std::string source, std::vector<std::string> &taken) {
    if (const auto slash = source.rfind('/');
        slash != std::string::npos && slash + 1 < source.size())
        source = source.substr(slash + 1);
    return link::recordingFileName(source, taken);
}

// A run that its --duration ended without a byte received failed (1), and says so.
int statusAtDuration(int rc, link::Connection &conn, double duration) {
    if (rc != 0 || duration <= 0 || conn.bytesReceived() > 0) return rc;
    std::fprintf(stderr, "gnss-cli: no data received from %s in %g s\n",
                 utf8(conn.transport()->description()).c_str(), duration);
    return 1;
}

void writeBaudTries(JsonWriter &w, const link::BaudDetection &d) {
    w.key("tried").beginArray();
    for (const auto &a : d.tried)
        w.beginObject()
                .field("baud", a.baud)
                .field("bytes", static_cast<std::int64_t>(a.bytes))
                .field("valid", a.validSentences)
                .field("invalid", a.badSentences)
                .field("rtcm_frames", a.rtcmFrames)
                .endObject();
    w.endArray();
}

} // namespace

int cmdPorts(const CliContext &) {
    EventLoop loop;
    for (const link::PortInfo &p : link::systemPorts()) {
        printJson([&](JsonWriter &w) {
            w.beginObject()
                    .field("port", utf8(p.portName))
                    .field("location", utf8(p.systemLocation))
                    .field("description", utf8(p.description))
                    .field("manufacturer", utf8(p.manufacturer))
                    .field("serial_number", utf8(p.serialNumber))
                    .field("usb_id", utf8(p.usbId()))
                    .endObject();
        });
    }
    return 0;
}

int cmdProbe(const CliContext &ctx) {
    const Args &args = ctx.args;
    EventLoop loop;
    link::BaudDetection found;
    OpenOptions o;
    o.autoReconnect = false;
    o.detection = &found;
    int rc = 0;
    auto conn = open(ctx, args, {Kind::Serial, Kind::Tcp, Kind::Gpsd, Kind::Simulator}, o, rc);
    if (!conn && found.tried.empty()) return rc;

    link::VendorIdentity id;
    if (conn) {
        link::VendorDetector vendor(conn->stream());
        QObject::connect(&vendor, &link::VendorDetector::finished,
                         [&](const link::VendorIdentity &v) {
                             id = v;
                             QCoreApplication::exit(v.found ? 0 : 1);
                         });
        QTimer::singleShot(0, &vendor, &link::VendorDetector::start);
        rc = loop.exec();
    }
    const auto port = args.option("port");
    std::string out;
    JsonWriter w(out);
    w.beginObject().field("source",
                          port ? *port : utf8(conn ? conn->transport()->description() : QString()));
    const int baud = found.found ? found.baud : (conn ? conn->transport()->baud() : 0);
    w.field("baud", baud > 0 ? std::optional<int>(baud) : std::nullopt);
    w.field("dialect", id.found ? std::optional<std::string>(utf8(id.dialect)) : std::nullopt);
    w.field("dialect_name",
            id.found ? std::optional<std::string>(utf8(id.dialectName)) : std::nullopt);
    w.field("model", textOrNull(id.model));
    w.field("firmware", textOrNull(id.firmware));
    w.field("method", textOrNull(id.method));
    w.field("reply", textOrNull(id.reply));
    writeBaudTries(w, found);
    const QString error = !conn ? found.error : id.error;
    w.field("error", textOrNull(error));
    w.endObject();
    printLine(out);
    if (rc != 0 && !error.isEmpty()) std::fprintf(stderr, "gnss-cli: %s\n", utf8(error).c_str());
    if (rc > 128) return rc; // interrupted
    return conn && rc == 0 ? 0 : 1;
}

int cmdMonitor(const CliContext &ctx) {
    const Args &args = ctx.args;
    double duration = 0;
    if (!numberOption(args, "duration", duration)) return 2;
    OpenOptions o;
    o.decoder.dialect = args.option("dialect").value_or("auto");
    o.decoder.lenient = args.flag("lenient");
    if (o.decoder.dialect != "auto" && !ctx.registry.find(o.decoder.dialect)) {
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s'\n", o.decoder.dialect.c_str());
        return 2;
    }
    EventLoop loop;
    // Nothing is missed: the decoder is listened to before the link opens.
    o.waitUntilOpen = false;
    int rc = 0;
    const std::initializer_list<Kind> kinds{Kind::Serial, Kind::Tcp, Kind::Gpsd, Kind::Replay,
                                            Kind::Simulator};
    std::vector<Opened> opened;
    if (sourceCount(args) > 1) {
        opened = openAll(ctx, args, kinds, o, rc);
    } else if (auto conn = open(ctx, args, kinds, o, rc)) {
        opened.push_back({std::move(conn), {}});
    }
    if (opened.empty()) return rc;
    // Several: each line says whose it is.
    const bool several = opened.size() > 1;
    const bool epochs = args.flag("epochs");
    std::vector<std::unique_ptr<EpochAssembler>> assemblers;
    std::vector<std::size_t> sentences(opened.size(), 0); // decoded ones
    std::size_t replays = 0, replayed = 0;
    for (std::size_t i = 0; i < opened.size(); ++i) {
        link::Connection *c = opened[i].connection.get();
        const std::string source = opened[i].source;
        auto print = [several, i, source](auto &&write) {
            std::string json;
            JsonWriter w(json);
            write(w);
            printLine(several ? tagged(json, i, source) : json);
        };
        assemblers.push_back(std::make_unique<EpochAssembler>(c->stream()->dialect()));
        EpochAssembler *assembler = assemblers.back().get();
        QObject::connect(c->stream(), &link::SentenceStream::sentenceDecoded,
                         [&, c, i, assembler, print](const SentenceEvent &ev) {
                             if (ev.message) ++sentences[i];
                             if (epochs) {
                                 if (!ev.message) return;
                                 assembler->setDialect(c->stream()->dialect());
                                 assembler->add(ev.sentence, *ev.message, [&](const Epoch &e) {
                                     print([&](JsonWriter &w) { e.writeJson(w); });
                                 });
                                 return;
                             }
                             print([&](JsonWriter &w) { writeSentenceEventJson(w, ev); });
                         });
        reportLinkEvents(*c, "");
        if (auto *replay = qobject_cast<link::ReplayTransport *>(c->transport())) {
            ++replays;
            // The end of the replays (all of them) ends the run.
            QObject::connect(replay, &link::ReplayTransport::finished, [&] {
                if (++replayed == replays && replays == opened.size()) QCoreApplication::exit(0);
            });
        }
    }
    loop.stopAfter(duration);
    rc = loop.exec();
    for (std::size_t i = 0; i < opened.size(); ++i) {
        link::Connection &c = *opened[i].connection;
        if (epochs)
            assemblers[i]->flush([&](const Epoch &e) {
                std::string json;
                JsonWriter w(json);
                e.writeJson(w);
                printLine(several ? tagged(json, i, opened[i].source) : json);
            });
        auto *replay = qobject_cast<link::ReplayTransport *>(c.transport());
        if (replay && replayed == replays && rc == 0 && sentences[i] == 0) {
            // A file that is not NMEA (or is empty) played to its end: said so, as `play` does.
            std::fprintf(stderr, "gnss-cli: %s: no NMEA found\n",
                         utf8(replay->description()).c_str());
            rc = 1;
        } else if (!replay) {
            rc = statusAtDuration(rc, c, duration);
        }
    }
    return rc;
}

int cmdRecord(const CliContext &ctx) {
    const Args &args = ctx.args;
    double duration = 0;
    if (!numberOption(args, "duration", duration)) return 2;
    const auto outPath = args.option("out");
    if (!outPath) {
        std::fprintf(stderr, "gnss-cli: record needs --out FILE\n");
        return 2;
    }
    EventLoop loop;
    OpenOptions o;
    o.waitUntilOpen = false;
    int rc = 0;
    const std::initializer_list<Kind> kinds{Kind::Serial, Kind::Tcp, Kind::Gpsd, Kind::Simulator};
    const bool several = sourceCount(args) > 1;
    std::vector<Opened> opened;
    if (several) {
        opened = openAll(ctx, args, kinds, o, rc);
    } else if (auto conn = open(ctx, args, kinds, o, rc)) {
        opened.push_back({std::move(conn), {}});
    }
    if (opened.empty()) return rc;
    // Several: --out is a folder, and each receiver's file is named after its source.
    std::vector<std::string> paths, taken;
    if (several) {
        const QString folder = QString::fromStdString(*outPath);
        if (!QDir().mkpath(folder)) {
            std::fprintf(stderr, "gnss-cli: cannot make the folder %s\n", outPath->c_str());
            return 1;
        }
        for (const Opened &x : opened)
            paths.push_back(QDir(folder)
                                    .filePath(QString::fromStdString(fileNameFor(x.source, taken)))
                                    .toStdString());
    } else {
        paths.push_back(*outPath);
    }
    for (std::size_t i = 0; i < opened.size(); ++i) {
        link::Connection &c = *opened[i].connection;
        reportLinkEvents(c, " (recording goes on)");
        if (!c.startRecording(QString::fromStdString(paths[i]))) {
            std::fprintf(stderr, "gnss-cli: %s\n", utf8(c.recorder()->errorString()).c_str());
            return 1;
        }
    }
    loop.stopAfter(duration);
    rc = loop.exec();
    for (std::size_t i = 0; i < opened.size(); ++i) {
        link::Connection &c = *opened[i].connection;
        c.stopRecording();
        std::fprintf(stderr, "gnss-cli: recorded %lld bytes to %s (index: %s)\n",
                     static_cast<long long>(c.bytesReceived()), paths[i].c_str(),
                     utf8(link::indexPathFor(QString::fromStdString(paths[i]))).c_str());
        rc = statusAtDuration(rc, c, duration);
    }
    return rc;
}

int cmdSend(const CliContext &ctx) {
    const Args &args = ctx.args;
    double timeout = -1;
    if (args.option("timeout") && !numberOption(args, "timeout", timeout)) return 2;
    if (args.positionals().empty()) {
        std::fprintf(stderr, "gnss-cli: send needs at least one SENTENCE\n");
        return 2;
    }
    // Every sentence is checked before anything is sent (its length too, when the dialect is
    // given: the queue would refuse what the receiver does not take).
    std::vector<std::string> lines;
    const bool fixChecksum = args.flag("fix-checksum");
    for (const auto &typed : args.positionals()) {
        std::string error, note;
        lines.push_back(checkTypedSentence(typed, fixChecksum, error, &note));
        if (lines.back().empty()) {
            std::fprintf(stderr, "gnss-cli: not a sentence: '%s' (%s); nothing was sent\n",
                         typed.c_str(), error.c_str());
            return 2;
        }
        if (!note.empty())
            std::fprintf(stderr, "gnss-cli: '%s': %s\n", typed.c_str(), note.c_str());
    }
    const std::string dialectId = args.option("dialect").value_or("auto");
    const Dialect *dialect = dialectId == "auto" ? nullptr : ctx.registry.find(dialectId);
    if (dialectId != "auto" && !dialect) {
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s'\n", dialectId.c_str());
        return 2;
    }
    for (std::size_t i = 0; dialect && i < lines.size(); ++i) {
        if (const QString why = link::lengthRefusal(lines[i], *dialect); !why.isEmpty()) {
            std::fprintf(stderr, "gnss-cli: '%s': %s; nothing was sent\n",
                         args.positionals()[i].c_str(), utf8(why).c_str());
            return 2;
        }
    }
    EventLoop loop;
    OpenOptions o;
    o.decoder.dialect = dialectId;
    o.autoReconnect = false;
    int rc = 0;
    auto conn = open(ctx, args, {Kind::Serial, Kind::Tcp, Kind::Simulator}, o, rc);
    if (!conn) return rc;
    link::CommandQueue *queue = conn->commands();
    if (dialect) queue->setDialect(dialect);
    int failures = 0;
    QObject::connect(
            queue, &link::CommandQueue::commandSent, [](int, const QString &s, int attempt) {
                std::fprintf(stderr, "> %s%s\n", utf8(s).c_str(), attempt > 1 ? " (again)" : "");
            });
    QObject::connect(queue, &link::CommandQueue::replyReceived, [](int, const QString &line) {
        std::fprintf(stderr, "< %s\n", utf8(line).c_str());
    });
    QObject::connect(queue, &link::CommandQueue::commandFinished,
                     [&](const link::CommandResult &r) {
                         if (r.outcome != link::CommandOutcome::Accepted &&
                             r.outcome != link::CommandOutcome::Sent)
                             ++failures;
                         printCommandResult(r, true);
                     });
    QObject::connect(queue, &link::CommandQueue::idle, [] { QCoreApplication::exit(0); });
    reportLinkEvents(*conn, "");
    link::CommandOptions co;
    if (timeout >= 0) co.timeoutMs = static_cast<int>(timeout * 1000);
    for (const auto &typed : args.positionals()) {
        QString why; // nothing is written before the loop runs
        if (queue->enqueue(QString::fromStdString(typed), co, &why) < 0) {
            std::fprintf(stderr, "gnss-cli: '%s': %s; nothing was sent\n", typed.c_str(),
                         utf8(why).c_str());
            return 2;
        }
    }
    rc = loop.exec();
    if (rc != 0) return rc;
    return failures == 0 ? 0 : 1;
}

} // namespace gnss::cli
