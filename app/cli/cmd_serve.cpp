// gnss-cli serve: a source's stream served to other programs. --ntrip [ADDR:]PORT/MOUNT is an
// NTRIP caster (revision 1 and 2) whose mountpoint carries the source's whole RTCM 3 frames;
// --raw [ADDR:]PORT passes the source's bytes, exactly, to every client. Both bind 127.0.0.1
// unless an address is given (then a warning says others can connect). Clients coming, going,
// refused and dropped (a client that does not read) are lines on standard error. The password
// is read from an environment variable (--password-env), never from the command line.
#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/event_loop.h"
#include "corrections/file_correction_source.h"
#include "corrections/rtcm_file_plan.h"
#include "link/replay_transport.h"
#include "ntrip/ntrip_request.h"
#include "serve/ntrip_caster.h"
#include "serve/raw_stream_server.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

namespace gnss::cli {
namespace {

void say(const std::string &s) {
    std::fprintf(stderr, "gnss-cli: %s\n", s.c_str());
}

struct Endpoint {
    QHostAddress address{QHostAddress::LocalHost};
    quint16 port = 0;
    QString text() const {
        const QString a = address.protocol() == QAbstractSocket::IPv6Protocol
                                  ? "[" + address.toString() + "]"
                                  : address.toString();
        return a + ":" + QString::number(port);
    }
};

// "[ADDR:]PORT": an address (127.0.0.1 when left out) and a port 0..65535 (0: a free one).
std::optional<Endpoint> parseEndpoint(const std::string &text, std::string &error) {
    const QString s = QString::fromStdString(text);
    const int colon = int(s.lastIndexOf(QLatin1Char(':')));
    Endpoint e;
    QString port = s;
    if (colon >= 0) {
        QString host = s.left(colon);
        if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
            host = host.mid(1, host.size() - 2);
        if (!e.address.setAddress(host)) {
            error = "'" + host.toStdString() + "' is not an IP address";
            return std::nullopt;
        }
        port = s.mid(colon + 1);
    }
    bool ok = false;
    const uint p = port.toUInt(&ok);
    if (!ok || p > 65535 || port.isEmpty() || !port.front().isDigit()) {
        error = "'" + port.toStdString() + "' is not a port (0 to 65535; 0: a free one)";
        return std::nullopt;
    }
    e.port = quint16(p);
    return e;
}

struct ServeOptions {
    std::optional<link::SourceSpec> source;
    bool loop = false;
    std::optional<Endpoint> ntrip;
    QString mount;
    QString user, password;
    std::optional<Endpoint> raw;
    double duration = 0;
};

bool readServeOptions(const Args &args, ServeOptions &o) {
    if (!args.error().empty()) return say(args.error()), false;
    using Kind = link::SourceSpec::Kind;
    std::string error;
    o.source =
            sourceFromArgs(args, {Kind::Serial, Kind::Tcp, Kind::Simulator, Kind::Replay}, error);
    if (!o.source) return say("serve: " + error), false;
    o.loop = args.flag("loop");
    if (o.loop && o.source->kind != Kind::Replay)
        return say("serve: --loop goes with --replay FILE"), false;
    if (const auto n = args.option("ntrip")) {
        const auto slash = n->find('/');
        if (slash == std::string::npos || slash + 1 == n->size())
            return say("serve: --ntrip takes [ADDR:]PORT/MOUNT, got '" + *n + "'"), false;
        o.ntrip = parseEndpoint(n->substr(0, slash), error);
        if (!o.ntrip) return say("serve: --ntrip: " + error), false;
        const std::string mount = n->substr(slash + 1);
        const std::string why = ntrip::checkMountpoint(mount);
        if (!why.empty()) return say("serve: --ntrip: " + why), false;
        o.mount = QString::fromStdString(mount);
    }
    if (const auto r = args.option("raw")) {
        o.raw = parseEndpoint(*r, error);
        if (!o.raw) return say("serve: --raw: " + error), false;
    }
    if (!o.ntrip && !o.raw)
        return say("serve: give --ntrip [ADDR:]PORT/MOUNT, --raw [ADDR:]PORT or both"), false;
    const auto user = args.option("user");
    const auto var = args.option("password-env");
    if (user.has_value() != var.has_value())
        return say("serve: --user and --password-env go together"), false;
    if (user && !o.ntrip) return say("serve: --user is for --ntrip"), false;
    if (user) {
        if (user->empty() || user->find(':') != std::string::npos)
            return say("serve: --user cannot be empty nor hold ':'"), false;
        const char *pw = std::getenv(var->c_str());
        if (!pw || !*pw)
            return say("serve: environment variable " + *var + " is not set or empty"), false;
        o.user = QString::fromStdString(*user);
        o.password = QString::fromLocal8Bit(pw);
    }
    if (const auto d = args.option("duration")) {
        bool ok = false;
        o.duration = QString::fromStdString(*d).toDouble(&ok);
        if (!ok || o.duration < 0) return say("serve: --duration expects seconds >= 0"), false;
    }
    return true;
}

std::string peerOf(const serve::ClientInfo &c) {
    return utf8(c.address.toString()) + ":" + std::to_string(c.port);
}

// Listening said (and a warning when others can connect); false when the port cannot be had.
template <class Server>
bool startListening(Server &server, const Endpoint &at, const std::string &what,
                    const std::string &tail) {
    if (!server.listen(at.address, at.port)) {
        say("cannot listen on " + utf8(at.text()) + " for the " + what + ": " +
            utf8(server.errorString()));
        return false;
    }
    const Endpoint bound{server.address(), server.port()};
    say(what + " on " + utf8(bound.text()) + tail);
    if (!at.address.isLoopback())
        say("warning: listening on " + utf8(at.address.toString()) +
            ": reachable from other machines");
    return true;
}

template <class Server> void reportClients(Server &server, const char *kind) {
    QObject::connect(&server, &Server::clientConnected, [kind](const serve::ClientInfo &c) {
        say(std::string(kind) + " client " + peerOf(c) + " connected");
    });
    QObject::connect(&server, &Server::clientDisconnected,
                     [kind](const serve::ClientInfo &c, const QString &why) {
                         say(std::string(kind) + " client " + peerOf(c) + " disconnected: " +
                             utf8(why) + " (" + std::to_string(c.bytesSent) + " bytes sent)");
                     });
    QObject::connect(&server, &Server::clientTurnedAway, [kind](const serve::ClientInfo &c) {
        say(std::string(kind) + " client " + peerOf(c) +
            " turned away: as many clients as allowed are served");
    });
}

} // namespace

int cmdServe(const CliContext &ctx) {
    ServeOptions o;
    if (!readServeOptions(ctx.args, o)) return 2;
    EventLoop loop;

    serve::NtripCaster caster;
    serve::RawStreamServer raw;
    if (o.ntrip) {
        serve::MountConfig mount;
        mount.name = o.mount;
        mount.needsPassword = !o.user.isEmpty();
        mount.describe.identifier = o.source->place().toStdString();
        caster.addMount(mount);
        if (!o.user.isEmpty()) caster.addUser(o.user, o.password);
        if (!startListening(caster, *o.ntrip, "NTRIP caster",
                            ", mountpoint " + utf8(o.mount) +
                                    (o.user.isEmpty() ? " (no password)" : "")))
            return 1;
        reportClients(caster, "NTRIP");
        QObject::connect(&caster, &serve::NtripCaster::streamStarted,
                         [](const serve::ClientInfo &c) {
                             say("NTRIP client " + peerOf(c) + " receives " + utf8(c.mountpoint) +
                                 (c.user.isEmpty() ? "" : " (user " + utf8(c.user) + ")"));
                         });
        QObject::connect(
                &caster, &serve::NtripCaster::requestRefused,
                [](const serve::ClientInfo &c, int status, const QString &why) {
                    say("NTRIP client " + peerOf(c) + " refused (" +
                        (status == 200 ? std::string("source table") : std::to_string(status)) +
                        "): " + utf8(why));
                });
    }
    if (o.raw) {
        if (!startListening(raw, *o.raw, "raw stream", "")) return 1;
        reportClients(raw, "raw");
    }
    auto publish = [&](const QByteArray &bytes) {
        if (o.ntrip) caster.publish(o.mount, bytes);
        if (o.raw) raw.publish(bytes);
    };

    // The source. A recorded file is played at its own pace from the first client on.
    std::unique_ptr<link::Connection> conn;
    std::unique_ptr<corrections::FileCorrectionSource> file;
    std::function<void()> startReplay;
    int rc = 0;
    if (o.source->kind == link::SourceSpec::Kind::Replay) {
        const QString path = o.source->name;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly)) return say("cannot read " + utf8(path)), 1;
        const QByteArray head = f.read(1 << 20);
        const bool rtcmFile = !QFileInfo::exists(path + ".idx") &&
                              corrections::planPlayback(
                                      std::string_view(head.constData(), std::size_t(head.size())))
                                              .frames > 0;
        if (rtcmFile) {
            file = std::make_unique<corrections::FileCorrectionSource>(path);
            file->setLoop(o.loop);
            file->setSpeed(o.source->speed);
            QObject::connect(file.get(), &corrections::CorrectionSource::dataReceived, publish);
            QObject::connect(file.get(), &corrections::CorrectionSource::stateChanged,
                             [&](corrections::CorrectionSource::State s) {
                                 if (s == corrections::CorrectionSource::State::Failed) {
                                     say(utf8(file->statusText()));
                                     QCoreApplication::exit(1);
                                 } else if (s == corrections::CorrectionSource::State::Idle &&
                                            !o.loop) { // played to its end
                                     say("the end of " + utf8(path) + " was served");
                                     QTimer::singleShot(500, [] { QCoreApplication::exit(0); });
                                 }
                             });
            startReplay = [&] { file->start(); };
        } else {
            OpenOptions open;
            open.autoReconnect = false;
            QString why;
            conn = openConnection(ctx, *o.source, open, why);
            if (!conn) return say("cannot open " + utf8(path) + ": " + utf8(why)), 1;
            auto *replay = qobject_cast<link::ReplayTransport *>(conn->transport());
            if (replay) {
                replay->pause();
                QObject::connect(replay, &link::ReplayTransport::finished, [&, replay] {
                    if (o.loop) return replay->seek(0);
                    say("the end of " + utf8(path) + " was served");
                    QTimer::singleShot(500, [] { QCoreApplication::exit(0); });
                });
                startReplay = [replay] { replay->resume(); };
            }
        }
        if (startReplay) {
            say("the replay starts when the first client is served");
            auto once = std::make_shared<bool>(false);
            auto begin = [&, once] {
                if (*once) return;
                *once = true;
                startReplay();
            };
            QObject::connect(&caster, &serve::NtripCaster::streamStarted, begin);
            QObject::connect(&raw, &serve::RawStreamServer::clientConnected, begin);
        }
    } else {
        OpenOptions open;
        QString why;
        conn = openConnection(ctx, *o.source, open, why);
        if (!conn)
            return EventLoop::interruptedStatus()
                           ? EventLoop::interruptedStatus()
                           : (say("cannot open the source: " + utf8(why)), 1);
        reportLinkEvents(*conn, "");
    }
    if (conn) QObject::connect(conn->transport(), &link::Transport::bytesReceived, publish);

    loop.stopAfter(o.duration);
    rc = loop.exec();
    if (file) {
        file->disconnect(); // stopped here: not the end of the file
        file->stop();
    }
    caster.close();
    raw.close();
    if (o.ntrip) {
        const serve::CasterCounters n = caster.counters();
        say("NTRIP: " + std::to_string(n.streams) + " streams, " + std::to_string(n.sourceTables) +
            " source tables, refused: " + std::to_string(n.unauthorized) + " unauthorized, " +
            std::to_string(n.notFound) + " unknown mountpoint, " +
            std::to_string(n.badRequests + n.notAllowed) +
            " malformed; dropped: " + std::to_string(n.droppedSlow) + " slow, " +
            std::to_string(n.headTimeouts) + " without a request, " +
            std::to_string(caster.overCapacity()) + " over the client limit");
    }
    if (o.raw)
        say("raw: dropped " + std::to_string(raw.droppedSlow()) + " slow, " +
            std::to_string(raw.overCapacity()) + " over the client limit");
    return rc;
}

} // namespace gnss::cli
