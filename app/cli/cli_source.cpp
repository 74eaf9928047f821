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

std::optional<link::SourceSpec>
sourceFromArgs(const Args &args, std::initializer_list<Kind> allowed, std::string &error) {
    std::optional<link::SourceSpec> found;
    int given = 0;
    for (const auto &o : kSourceOptions) {
        const auto v = args.option(o.option);
        if (!v) continue;
        ++given;
        if (!allowedKind(allowed, o.kind)) {
            error = std::string("this command does not take --") + o.option;
            return std::nullopt;
        }
        link::SourceSpec s;
        s.kind = o.kind;
        s.name = QString::fromStdString(*v);
        found = s;
    }
    if (given != 1) {
        error = "give one source: " + sourceOptionsText(allowed);
        return std::nullopt;
    }
    if (found->kind == Kind::Gpsd) {
        // Checked here so that a malformed one is a usage error, not a failure to connect.
        link::GpsdTransport::Target target;
        QString why;
        if (!link::GpsdTransport::parseTarget(found->name, target, &why)) {
            error = "--gpsd: " + why.toStdString();
            return std::nullopt;
        }
        // The name is what follows the scheme, as the GUI keeps it.
        found->name = found->name.trimmed();
        if (found->name.startsWith(QLatin1String("gpsd://"), Qt::CaseInsensitive))
            found->name = found->name.mid(7);
    }
    if (found->kind == Kind::Tcp) {
        // A malformed HOST:PORT is a usage error too (a misspelled one is a failure to connect).
        QString host;
        quint16 port = 0;
        if (!link::TcpTransport::parseHostPort(found->name, host, port)) {
            error = "--tcp takes HOST:PORT (a port from 1 to 65535), got '" +
                    found->name.toStdString() + "'";
            return std::nullopt;
        }
    }
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

std::unique_ptr<link::Connection> openConnection(const CliContext &ctx,
                                                 const link::SourceSpec &spec,
                                                 const OpenOptions &options, QString &error,
                                                 bool *refused) {
    if (!ctx.transports) {
        error = QStringLiteral("no transports in this program");
        return nullptr;
    }
    link::LinkOpener opener(*ctx.transports, ctx.registry);
    QEventLoop loop;
    bool failed = false;
    QObject::connect(&opener, &link::LinkOpener::tryingRate, [&opener](int baud) {
        const int before = int(opener.detection().tried.size()) - 1;
        if (before > 0)
            std::fprintf(
                    stderr, "gnss-cli: baud %s; trying %d\n",
                    link::LinkOpener::attemptsText(opener.detection(), before).toUtf8().constData(),
                    baud);
        else
            std::fprintf(stderr, "gnss-cli: detecting the baud rate: trying %d\n", baud);
    });
    QObject::connect(&opener, &link::LinkOpener::ready, &loop, &QEventLoop::quit);
    QObject::connect(&opener, &link::LinkOpener::failed, [&](const QString &why) {
        failed = true;
        error = why;
        loop.quit();
    });
    opener.start(spec, options.decoder);
    if (opener.isDetecting()) loop.exec();
    if (options.detection) *options.detection = opener.detection();
    if (failed) return nullptr;
    std::unique_ptr<link::Connection> conn = opener.takeConnection();
    if (!conn) {
        error = QStringLiteral("no connection");
        return nullptr;
    }
    if (!opener.detection().tried.empty())
        std::fprintf(stderr, "gnss-cli: baud %d found (%s)\n", opener.detection().baud,
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
