#include "cli/cli_source.h"

#include "cli/cli_output.h"
#include "core/json_writer.h"
#include "link/gpsd_transport.h"
#include "link/link_opener.h"
#include "link/tcp_transport.h"
#include "link/transport_factory.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cstdio>

namespace gnss::cli {

namespace {

using Kind = link::SourceSpec::Kind;

struct SourceOption {
    Kind kind;
    const char *option;
    const char *usage;
};
constexpr SourceOption kSourceOptions[] = {
        {Kind::Serial, "port", "--port P [--baud B]"},
        {Kind::Tcp, "tcp", "--tcp HOST:PORT"},
        {Kind::Gpsd, "gpsd", "--gpsd HOST[:PORT][/DEVICE]"},
        {Kind::Replay, "replay", "--replay FILE [--speed X] [--fast]"},
        {Kind::Simulator, "sim", "--sim DIALECT [--baud B]"},
};

bool allowedKind(std::initializer_list<Kind> allowed, Kind k) {
    return std::find(allowed.begin(), allowed.end(), k) != allowed.end();
}

} // namespace

std::string sourceOptionsText(std::initializer_list<Kind> allowed) {
    std::string out;
    for (const auto &o : kSourceOptions) {
        if (!allowedKind(allowed, o.kind)) continue;
        if (!out.empty()) out += " | ";
        out += o.usage;
    }
    return out;
}

std::optional<Kind> sourceKindOf(std::string_view option) {
    for (const auto &o : kSourceOptions)
        if (option == o.option) return o.kind;
    return std::nullopt;
}

std::optional<link::SourceSpec> sourceSpecOf(Kind kind, const std::string &value,
                                             std::string &error) {
    link::SourceSpec s;
    s.kind = kind;
    s.name = QString::fromStdString(value);
    if (kind == Kind::Gpsd) {
        // Checked here so that a malformed one is a usage error, not a failure to connect.
        link::GpsdTransport::Target target;
        QString why;
        if (!link::GpsdTransport::parseTarget(s.name, target, &why)) {
            error = "--gpsd: " + why.toStdString();
            return std::nullopt;
        }
        // The name is what follows the scheme, as the GUI keeps it.
        s.name = s.name.trimmed();
        if (s.name.startsWith(QLatin1String("gpsd://"), Qt::CaseInsensitive))
            s.name = s.name.mid(7);
    }
    if (kind == Kind::Tcp) {
        // A malformed HOST:PORT is a usage error too (a misspelled one is a failure to connect).
        QString host;
        quint16 port = 0;
        if (!link::TcpTransport::parseHostPort(s.name, host, port)) {
            error = "--tcp takes HOST:PORT (a port from 1 to 65535), got '" + value + "'";
            return std::nullopt;
        }
    }
    return s;
}

std::optional<link::SourceSpec>
sourceFromArgs(const Args &args, std::initializer_list<Kind> allowed, std::string &error) {
    std::optional<std::pair<Kind, std::string>> given;
    int count = 0;
    for (const auto &o : kSourceOptions) {
        const auto v = args.option(o.option);
        if (!v) continue;
        ++count;
        if (!allowedKind(allowed, o.kind)) {
            error = std::string("this command does not take --") + o.option;
            return std::nullopt;
        }
        given = {o.kind, *v};
    }
    if (count != 1) {
        error = "give one source: " + sourceOptionsText(allowed);
        return std::nullopt;
    }
    auto found = sourceSpecOf(given->first, given->second, error);
    if (!found) return std::nullopt;
    if (const auto b = args.option("baud")) {
        bool ok = false;
        found->baud = QString::fromStdString(*b).toInt(&ok);
        if (!ok || found->baud < 300 || found->baud > 4000000) {
            error = "--baud expects a speed such as 9600 or 115200, got '" + *b + "'";
            return std::nullopt;
        }
    }
    if (const auto sp = args.option("speed")) {
        bool ok = false;
        found->speed = QString::fromStdString(*sp).toDouble(&ok);
        if (!ok || found->speed <= 0) {
            error = "--speed expects a factor above 0, got '" + *sp + "'";
            return std::nullopt;
        }
    }
    found->asFast = args.flag("fast");
    return found;
}

namespace {

// What is left to open a connection once its opener is done (its speed found, or not needed).
std::unique_ptr<link::Connection> finishOpening(link::LinkOpener &opener, bool failed,
                                                const OpenOptions &options,
                                                const std::string &label, QString &error,
                                                bool *refused) {
    if (failed) return nullptr;
    std::unique_ptr<link::Connection> conn = opener.takeConnection();
    if (!conn) {
        error = QStringLiteral("no connection");
        return nullptr;
    }
    if (!opener.detection().tried.empty())
        std::fprintf(stderr, "gnss-cli: %sbaud %d found (%s)\n", label.c_str(),
                     opener.detection().baud,
                     link::LinkOpener::attemptsText(opener.detection()).toUtf8().constData());
    conn->setAutoReconnect(options.autoReconnect);
    if (!conn->open()) {
        error = conn->transport()->errorString();
        return nullptr;
    }
    if (options.waitUntilOpen && !conn->transport()->isOpen()) {
        // A TCP connect or a log being indexed: wait for it, or for its failure.
        QEventLoop wait;
        QObject::connect(conn.get(), &link::Connection::opened, &wait, &QEventLoop::quit);
        QObject::connect(conn.get(), &link::Connection::openFailed, &wait,
                         [&](const QString &why, int) {
                             error = why;
                             wait.quit();
                         });
        QTimer::singleShot(options.openTimeoutMs, &wait, &QEventLoop::quit);
        wait.exec();
        if (!conn->transport()->isOpen()) {
            if (refused) *refused = conn->transport()->errorIsRequest();
            if (error.isEmpty())
                error = QStringLiteral("%1: not open after %2 s")
                                .arg(conn->transport()->description())
                                .arg(options.openTimeoutMs / 1000);
            return nullptr;
        }
    }
    return conn;
}

} // namespace

std::vector<std::unique_ptr<link::Connection>>
openConnections(const CliContext &ctx, const std::vector<link::SourceSpec> &specs,
                const OpenOptions &options, QString &error, bool *refused) {
    if (!ctx.transports) {
        error = QStringLiteral("no transports in this program");
        return {};
    }
    // Every source's speed is looked for at once: four ports take as long as the slowest.
    struct Opening {
        std::unique_ptr<link::LinkOpener> opener;
        bool done = false, failed = false;
        QString why;
        std::string label; // "PORT: " before its messages when there are several
    };
    std::vector<Opening> openings(specs.size());
    QEventLoop loop;
    std::size_t pending = 0;
    auto finished = [&](Opening &o) {
        if (o.done) return;
        o.done = true;
        if (--pending == 0) loop.quit();
    };
    for (std::size_t i = 0; i < specs.size(); ++i) {
        Opening &o = openings[i];
        o.opener = std::make_unique<link::LinkOpener>(*ctx.transports, ctx.registry);
        if (specs.size() > 1) o.label = specs[i].name.toStdString() + ": ";
        link::LinkOpener *opener = o.opener.get();
        QObject::connect(opener, &link::LinkOpener::tryingRate, [opener, &o](int baud) {
            const int before = int(opener->detection().tried.size()) - 1;
            if (before > 0)
                std::fprintf(stderr, "gnss-cli: %sbaud %s; trying %d\n", o.label.c_str(),
                             link::LinkOpener::attemptsText(opener->detection(), before)
                                     .toUtf8()
                                     .constData(),
                             baud);
            else
                std::fprintf(stderr, "gnss-cli: %sdetecting the baud rate: trying %d\n",
                             o.label.c_str(), baud);
        });
        QObject::connect(opener, &link::LinkOpener::ready, [&o, finished] { finished(o); });
        QObject::connect(opener, &link::LinkOpener::failed, [&o, finished](const QString &why) {
            o.failed = true;
            o.why = why;
            finished(o);
        });
        ++pending;
        opener->start(specs[i], options.decoder);
        if (!opener->isDetecting() && !o.done) {
            o.done = true;
            --pending;
        }
    }
    if (pending > 0) loop.exec();
    if (options.detection && !openings.empty())
        *options.detection = openings.front().opener->detection();
    std::vector<std::unique_ptr<link::Connection>> out;
    for (Opening &o : openings) {
        error = o.why;
        auto conn = finishOpening(*o.opener, o.failed, options, o.label, error, refused);
        if (!conn) return {};
        out.push_back(std::move(conn));
    }
    return out;
}

std::unique_ptr<link::Connection> openConnection(const CliContext &ctx,
                                                 const link::SourceSpec &spec,
                                                 const OpenOptions &options, QString &error,
                                                 bool *refused) {
    auto all = openConnections(ctx, {spec}, options, error, refused);
    return all.empty() ? nullptr : std::move(all.front());
}

// Link events on standard error; a link that cannot be opened and will not be retried ends the
// command with status 1.
void reportLinkEvents(link::Connection &conn, const char *note) {
    link::Transport *transport = conn.transport();
    QObject::connect(&conn, &link::Connection::openFailed,
                     [note, transport](const QString &why, int retryMs) {
                         if (retryMs <= 0) {
                             std::fprintf(stderr, "gnss-cli: %s\n", utf8(why).c_str());
                             // A device gpsd does not have is the request's fault (2), not the
                             // source's (1).
                             QCoreApplication::exit(transport->errorIsRequest() ? 2 : 1);
                             return;
                         }
                         std::fprintf(stderr, "gnss-cli: %s; trying again in %d s%s\n",
                                      utf8(why).c_str(), (retryMs + 500) / 1000, note);
                     });
    QObject::connect(&conn, &link::Connection::linkLost, [note](const QString &why, int retryMs) {
        std::fprintf(stderr, "gnss-cli: link lost: %s; trying again in %d s%s\n", utf8(why).c_str(),
                     (retryMs + 500) / 1000, note);
    });
    QObject::connect(&conn, &link::Connection::linkRestored, [](const QString &what) {
        std::fprintf(stderr, "gnss-cli: link back: %s\n", utf8(what).c_str());
    });
}

void printCommandResult(const link::CommandResult &r, bool timing) {
    printJson([&](JsonWriter &w) {
        w.beginObject()
                .field("sentence", utf8(r.sentence))
                .field("outcome", utf8(link::outcomeName(r.outcome)))
                .field("detail", utf8(r.detail));
        if (timing)
            w.field("attempts", r.attempts).field("ms", static_cast<std::int64_t>(r.elapsedMs));
        w.key("replies").beginArray();
        for (const QString &line : r.replies) w.value(utf8(line));
        w.endArray();
        if (r.baudAfter > 0) w.field("baud", r.baudAfter);
        w.endObject();
    });
}

} // namespace gnss::cli
