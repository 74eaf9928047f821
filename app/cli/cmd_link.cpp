// gnss-cli ports | probe | monitor | record | send: the link layer (protocol/link) from the
// command line. These commands need Qt's event loop, so each creates its QCoreApplication; the
// file-based commands (decode, epochs, ...) stay Qt-free.
// Before any Qt header: it has a member named emit, which Qt defines as a macro.
#include "state/epoch_assembler.h"

#include "baud_detector.h"
#include "cli_args.h"
#include "cli_commands.h"
#include "connection.h"
#include "core/json_writer.h"
#include "core/sentence_builder.h"
#include "port_watcher.h"
#include "replay_transport.h"
#include "serial_transport.h"
#include "tcp_transport.h"
#include "vendor_detector.h"

#include <QCoreApplication>
#include <QTimer>

#include <csignal>
#include <cstdio>
#include <memory>

namespace gnss::cli {
namespace {

volatile std::sig_atomic_t g_stop = 0; // the signal that asked to stop
void onSignal(int signal) {
    g_stop = signal;
}

// The QCoreApplication these commands need, plus Ctrl-C/SIGTERM ending the event loop (so
// recordings are flushed and closed, not cut) with the status a shell gives a program the signal
// killed: 128 + its number (130 for Ctrl-C), so scripts can tell an interruption from an end.
struct EventLoop {
    int argc = 1;
    char name[9] = "gnss-cli";
    char *argv[2] = {name, nullptr};
    QCoreApplication app{argc, argv};
    QTimer signalPoll;
    EventLoop() {
        g_stop = 0;
        std::signal(SIGINT, onSignal);
        std::signal(SIGTERM, onSignal);
        QObject::connect(&signalPoll, &QTimer::timeout, [] {
            if (g_stop) QCoreApplication::exit(128 + g_stop);
        });
        signalPoll.start(100);
    }
    // Ends the loop after `seconds` (none when <= 0).
    void stopAfter(double seconds) {
        if (seconds > 0)
            QTimer::singleShot(static_cast<int>(seconds * 1000), &app,
                               [] { QCoreApplication::exit(0); });
    }
    int exec() { return app.exec(); }
};

void printLine(const std::string &s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

std::string utf8(const QString &s) {
    return s.toStdString();
}

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

bool baudOption(const Args &args, int &baud) {
    const auto v = args.option("baud");
    if (!v) return true;
    bool ok = false;
    baud = QString::fromStdString(*v).toInt(&ok);
    if (!ok || baud < 300 || baud > 4000000) {
        std::fprintf(stderr, "gnss-cli: --baud expects a speed such as 9600 or 115200, got '%s'\n",
                     v->c_str());
        return false;
    }
    return true;
}

// The source named by --port/--tcp/--replay (exactly one); nullptr with a message when wrong.
std::unique_ptr<link::Transport> makeSource(const Args &args, int baud, bool allowReplay) {
    const auto port = args.option("port");
    const auto tcp = args.option("tcp");
    const auto replay = allowReplay ? args.option("replay") : std::nullopt;
    const int given = (port ? 1 : 0) + (tcp ? 1 : 0) + (replay ? 1 : 0);
    if (given != 1) {
        std::fprintf(stderr, allowReplay ? "gnss-cli: give one of --port P, --tcp HOST:PORT or "
                                           "--replay FILE\n"
                                         : "gnss-cli: give one of --port P or --tcp HOST:PORT\n");
        return nullptr;
    }
    if (port) {
        link::SerialSettings s;
        s.portName = QString::fromStdString(*port);
        s.baud = baud;
        return std::make_unique<link::SerialTransport>(s);
    }
    if (tcp) {
        QString host;
        quint16 p = 0;
        if (!link::TcpTransport::parseHostPort(QString::fromStdString(*tcp), host, p)) {
            std::fprintf(stderr, "gnss-cli: --tcp expects HOST:PORT, got '%s'\n", tcp->c_str());
            return nullptr;
        }
        return std::make_unique<link::TcpTransport>(host, p);
    }
    auto r = std::make_unique<link::ReplayTransport>(QString::fromStdString(*replay));
    double speed = 1;
    if (!numberOption(args, "speed", speed)) return nullptr;
    if (speed > 0) r->setSpeed(speed);
    if (args.flag("fast"))
        r = std::make_unique<link::ReplayTransport>(QString::fromStdString(*replay),
                                                    link::ReplayTransport::Timing::AsFast);
    return r;
}

// Link events on standard error; a link that cannot be opened and will not be retried ends the
// command with status 1.
void reportLinkEvents(link::Connection &conn, const char *note) {
    QObject::connect(&conn, &link::Connection::openFailed, [note](const QString &why, int retryMs) {
        if (retryMs <= 0) {
            std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
            QCoreApplication::exit(1);
            return;
        }
        std::fprintf(stderr, "gnss-cli: %s; trying again in %d s%s\n", utf8(why).c_str(),
                     (retryMs + 500) / 1000, note);
    });
    QObject::connect(&conn, &link::Connection::linkLost, [note](const QString &why, int retryMs) {
        std::fprintf(stderr, "gnss-cli: link lost: %s; trying again in %d s%s\n", utf8(why).c_str(),
                     (retryMs + 500) / 1000, note);
    });
    QObject::connect(&conn, &link::Connection::linkRestored, [](const QString &what) {
        std::fprintf(stderr, "gnss-cli: link back: %s\n", utf8(what).c_str());
    });
}

bool openOrSay(link::Transport &t) {
    if (t.open()) return true;
    std::fprintf(stderr, "gnss-cli: %s\n", utf8(t.errorString()).c_str());
    return false;
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
        std::string out;
        JsonWriter w(out);
        w.beginObject()
                .field("port", utf8(p.portName))
                .field("location", utf8(p.systemLocation))
                .field("description", utf8(p.description))
                .field("manufacturer", utf8(p.manufacturer))
                .field("serial_number", utf8(p.serialNumber))
                .field("usb_id", utf8(p.usbId()))
                .endObject();
        printLine(out);
    }
    return 0;
}

int cmdProbe(const CliContext &ctx) {
    const Args &args = ctx.args;
    int baud = 0;
    if (!baudOption(args, baud)) return 2;
    if (!args.option("port")) {
        std::fprintf(stderr, "gnss-cli: probe needs --port P\n");
        return 2;
    }
    EventLoop loop;
    auto source = makeSource(args, baud > 0 ? baud : 9600, false);
    if (!source || !openOrSay(*source)) return source ? 1 : 2;

    link::BaudDetector baudDetector(source.get());
    baudDetector.setCandidates(link::BaudDetector::likelyRates(baud));
    link::VendorDetector vendor(source.get(), ctx.registry);
    link::BaudDetection found;
    link::VendorIdentity id;
    QObject::connect(&baudDetector, &link::BaudDetector::finished,
                     [&](const link::BaudDetection &d) {
                         found = d;
                         if (!d.found) return QCoreApplication::exit(1);
                         vendor.start();
                     });
    QObject::connect(&vendor, &link::VendorDetector::finished, [&](const link::VendorIdentity &v) {
        id = v;
        QCoreApplication::exit(v.found ? 0 : 1);
    });
    QTimer::singleShot(0, &baudDetector, &link::BaudDetector::start);
    const int rc = loop.exec();

    std::string out;
    JsonWriter w(out);
    w.beginObject().field("port", *args.option("port"));
    w.field("baud", found.found ? std::optional<int>(found.baud) : std::nullopt);
    w.field("dialect", id.found ? std::optional<std::string>(utf8(id.dialect)) : std::nullopt);
    w.field("dialect_name",
            id.found ? std::optional<std::string>(utf8(id.dialectName)) : std::nullopt);
    w.field("model",
            id.model.isEmpty() ? std::nullopt : std::optional<std::string>(utf8(id.model)));
    w.field("firmware",
            id.firmware.isEmpty() ? std::nullopt : std::optional<std::string>(utf8(id.firmware)));
    w.field("method",
            id.method.isEmpty() ? std::nullopt : std::optional<std::string>(utf8(id.method)));
    w.field("reply",
            id.reply.isEmpty() ? std::nullopt : std::optional<std::string>(utf8(id.reply)));
    writeBaudTries(w, found);
    const QString error = !found.found ? found.error : id.error;
    w.field("error", error.isEmpty() ? std::nullopt : std::optional<std::string>(utf8(error)));
    w.endObject();
    printLine(out);
    if (rc != 0 && !error.isEmpty()) std::fprintf(stderr, "gnss-cli: %s\n", utf8(error).c_str());
    return rc == 0 || rc > 128 ? rc : 1;
}

int cmdMonitor(const CliContext &ctx) {
    const Args &args = ctx.args;
    int baud = 0;
    double duration = 0;
    if (!baudOption(args, baud) || !numberOption(args, "duration", duration)) return 2;
    DecoderOptions options;
    options.dialect = args.option("dialect").value_or("auto");
    options.lenient = args.flag("lenient");
    if (options.dialect != "auto" && !ctx.registry.find(options.dialect)) {
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s'\n", options.dialect.c_str());
        return 2;
    }
    EventLoop loop;
    auto source = makeSource(args, baud > 0 ? baud : 9600, true);
    if (!source) return 2;
    auto *replay = qobject_cast<link::ReplayTransport *>(source.get());
    link::Connection conn(std::move(source), ctx.registry, options);
    const bool epochs = args.flag("epochs");
    EpochAssembler assembler(conn.decoder().dialect());
    auto onEpoch = [](const Epoch &e) {
        std::string out;
        JsonWriter w(out);
        e.writeJson(w);
        printLine(out);
    };
    conn.setSentenceHandler([&](const SentenceEvent &ev) {
        if (epochs) {
            if (!ev.message) return;
            assembler.setDialect(conn.decoder().dialect());
            assembler.add(ev.sentence, *ev.message, onEpoch);
            return;
        }
        std::string out;
        JsonWriter w(out);
        writeSentenceEventJson(w, ev);
        printLine(out);
    });
    reportLinkEvents(conn, "");
    if (replay)
        QObject::connect(replay, &link::ReplayTransport::finished,
                         [] { QCoreApplication::exit(0); });
    if (!conn.open()) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(conn.transport()->errorString()).c_str());
        return 1;
    }
    loop.stopAfter(duration);
    const int rc = loop.exec();
    if (epochs) assembler.flush(onEpoch);
    return rc;
}

int cmdRecord(const CliContext &ctx) {
    const Args &args = ctx.args;
    int baud = 0;
    double duration = 0;
    if (!baudOption(args, baud) || !numberOption(args, "duration", duration)) return 2;
    const auto outPath = args.option("out");
    if (!outPath) {
        std::fprintf(stderr, "gnss-cli: record needs --out FILE\n");
        return 2;
    }
    EventLoop loop;
    auto source = makeSource(args, baud > 0 ? baud : 9600, false);
    if (!source) return 2;
    link::Connection conn(std::move(source), ctx.registry);
    reportLinkEvents(conn, " (recording goes on)");
    if (!conn.startRecording(QString::fromStdString(*outPath))) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(conn.recorder()->errorString()).c_str());
        return 1;
    }
    if (!conn.open()) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(conn.transport()->errorString()).c_str());
        return 1;
    }
    loop.stopAfter(duration);
    const int rc = loop.exec();
    conn.stopRecording();
    std::fprintf(stderr, "gnss-cli: recorded %lld bytes to %s (index: %s)\n",
                 static_cast<long long>(conn.bytesReceived()), outPath->c_str(),
                 utf8(link::indexPathFor(QString::fromStdString(*outPath))).c_str());
    return rc;
}

int cmdSend(const CliContext &ctx) {
    const Args &args = ctx.args;
    int baud = 0;
    double timeout = -1;
    if (!baudOption(args, baud)) return 2;
    if (args.option("timeout") && !numberOption(args, "timeout", timeout)) return 2;
    if (args.positionals().empty()) {
        std::fprintf(stderr, "gnss-cli: send needs at least one SENTENCE\n");
        return 2;
    }
    // Every sentence is checked before anything is sent.
    for (const auto &typed : args.positionals()) {
        std::string error;
        if (completeSentence(typed, error).empty()) {
            std::fprintf(stderr, "gnss-cli: not a sentence: '%s' (%s); nothing was sent\n",
                         typed.c_str(), error.c_str());
            return 2;
        }
    }
    const std::string dialectId = args.option("dialect").value_or("auto");
    const Dialect *dialect = dialectId == "auto" ? nullptr : ctx.registry.find(dialectId);
    if (dialectId != "auto" && !dialect) {
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s'\n", dialectId.c_str());
        return 2;
    }
    EventLoop loop;
    auto source = makeSource(args, baud > 0 ? baud : 9600, false);
    if (!source) return 2;
    DecoderOptions options;
    options.dialect = dialectId;
    link::Connection conn(std::move(source), ctx.registry, options);
    conn.setAutoReconnect(false);
    link::CommandQueue *queue = conn.commands();
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
                         std::string out;
                         JsonWriter w(out);
                         w.beginObject()
                                 .field("sentence", utf8(r.sentence))
                                 .field("outcome", utf8(link::outcomeName(r.outcome)))
                                 .field("detail", utf8(r.detail))
                                 .field("attempts", r.attempts)
                                 .field("ms", static_cast<std::int64_t>(r.elapsedMs));
                         w.key("replies").beginArray();
                         for (const QString &line : r.replies) w.value(utf8(line));
                         w.endArray();
                         if (r.baudAfter > 0) w.field("baud", r.baudAfter);
                         w.endObject();
                         printLine(out);
                     });
    QObject::connect(queue, &link::CommandQueue::idle, [] { QCoreApplication::exit(0); });
    reportLinkEvents(conn, "");
    if (!conn.open()) {
        std::fprintf(stderr, "gnss-cli: %s\n", utf8(conn.transport()->errorString()).c_str());
        return 1;
    }
    link::CommandOptions o;
    if (timeout >= 0) o.timeoutMs = static_cast<int>(timeout * 1000);
    for (const auto &typed : args.positionals()) queue->enqueue(QString::fromStdString(typed), o);
    const int rc = loop.exec();
    if (rc != 0) return rc;
    return failures == 0 ? 0 : 1;
}

} // namespace gnss::cli
