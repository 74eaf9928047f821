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
#include "link/replay_transport.h"
#include "link/sentence_stream.h"
#include "link/vendor_detector.h"

#include <QCoreApplication>
#include <QTimer>

#include <cstdio>
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
    // A log that cannot be replayed (missing, or an index that contradicts it) stays so: it is
    // not retried, the command ends saying why.
    OpenOptions o = options;
    if (spec->kind == Kind::Replay) o.autoReconnect = false;
    QString why;
    bool refused = false;
    auto conn = openConnection(ctx, *spec, o, why, &refused);
    if (!conn) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
        rc = refused ? 2 : 1;
    }
    return conn;
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
    auto conn = open(ctx, args,
                     {Kind::Serial, Kind::Tcp, Kind::Gpsd, Kind::Replay, Kind::Simulator}, o, rc);
    if (!conn) return rc;
    auto *replay = qobject_cast<link::ReplayTransport *>(conn->transport());
    const bool epochs = args.flag("epochs");
    EpochAssembler assembler(conn->stream()->dialect());
    auto onEpoch = [](const Epoch &e) { printJson([&](JsonWriter &w) { e.writeJson(w); }); };
    link::Connection *c = conn.get();
    std::size_t sentences = 0; // decoded ones
    QObject::connect(c->stream(), &link::SentenceStream::sentenceDecoded,
                     [&, c](const SentenceEvent &ev) {
                         if (ev.message) ++sentences;
                         if (epochs) {
                             if (!ev.message) return;
                             assembler.setDialect(c->stream()->dialect());
                             assembler.add(ev.sentence, *ev.message, onEpoch);
                             return;
                         }
                         printJson([&](JsonWriter &w) { writeSentenceEventJson(w, ev); });
                     });
    reportLinkEvents(*c, "");
    bool replayed = false; // to its end
    if (replay)
        QObject::connect(replay, &link::ReplayTransport::finished, [&replayed] {
            replayed = true;
            QCoreApplication::exit(0);
        });
    loop.stopAfter(duration);
    rc = loop.exec();
    if (epochs) assembler.flush(onEpoch);
    if (replayed && rc == 0 && sentences == 0) {
        // A file that is not NMEA (or is empty) played to its end: said so, as `play` does.
        std::fprintf(stderr, "gnss-cli: %s: no NMEA found\n", utf8(replay->description()).c_str());
        return 1;
    }
    return replay ? rc : statusAtDuration(rc, *c, duration);
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
    auto conn = open(ctx, args, {Kind::Serial, Kind::Tcp, Kind::Gpsd, Kind::Simulator}, o, rc);
    if (!conn) return rc;
    reportLinkEvents(*conn, " (recording goes on)");
    if (!conn->startRecording(QString::fromStdString(*outPath))) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(conn->recorder()->errorString()).c_str());
        return 1;
    }
    loop.stopAfter(duration);
    rc = loop.exec();
    conn->stopRecording();
    std::fprintf(stderr, "gnss-cli: recorded %lld bytes to %s (index: %s)\n",
                 static_cast<long long>(conn->bytesReceived()), outPath->c_str(),
                 utf8(link::indexPathFor(QString::fromStdString(*outPath))).c_str());
    return statusAtDuration(rc, *conn, duration);
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
