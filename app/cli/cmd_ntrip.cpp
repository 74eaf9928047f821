// gnss-cli ntrip: an NTRIP caster from the command line. Prints its source table as JSON lines
// (with each stream's distance when a position is given), or receives a mountpoint's RTCM and
// prints one JSON line per message (the same objects as `gnss-cli rtcm`) and/or writes the raw
// bytes to a file. A refusal ends it with exit code 1 (wrong password ...) or 2 (unknown
// mountpoint) and the reason in words; a dropped connection is retried with the backoff and said on
// standard error. The password is read from an environment variable, never from the command
// line (where `ps` would show it), and is never printed.
#include "rtcm/rtcm_json.h"
#include "rtcm/rtcm_stream_decoder.h"

#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "cli/cli_output.h"
#include "cli/cli_source.h"
#include "cli/event_loop.h"
#include "core/json_writer.h"
#include "corrections/correction_forwarder.h"
#include "corrections/ntrip_source.h"
#include "corrections/rover_position.h"
#include "corrections/source_table_request.h"
#include "link/sentence_stream.h"
#include "link/tcp_transport.h"
#include "ntrip/mountpoint_distance.h"
#include "ntrip/redact.h"
#include "state/epoch_assembler.h"

#include <QCoreApplication>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace gnss::cli {
namespace {

void say(const std::string &s) {
    std::fprintf(stderr, "gnss-cli: %s\n", s.c_str());
}

// "LAT,LON,H" in degrees and metres.
std::optional<ntrip::GgaPosition> parsePosition(const std::string &text) {
    const QStringList parts = QString::fromStdString(text).split(QLatin1Char(','));
    if (parts.size() != 3) return std::nullopt;
    bool ok[3] = {};
    ntrip::GgaPosition p;
    p.latDeg = parts[0].toDouble(&ok[0]);
    p.lonDeg = parts[1].toDouble(&ok[1]);
    p.altitudeMsl = parts[2].toDouble(&ok[2]);
    if (!ok[0] || !ok[1] || !ok[2] || std::fabs(p.latDeg) > 90 || std::fabs(p.lonDeg) > 180 ||
        !std::isfinite(p.altitudeMsl))
        return std::nullopt;
    return p;
}

std::optional<double> km(const std::optional<ntrip::GgaPosition> &from,
                         const ntrip::StreamEntry &s) {
    const auto at = ntrip::entryPosition(s);
    if (!from || !at) return std::nullopt;
    return std::round(ntrip::greatCircleMetres(from->latDeg, from->lonDeg, at->first, at->second) /
                      100.0) /
           10.0;
}

// One JSON line per record: its tag ("STR", "CAS", "NET") as "type", then its fields in the
// source table's order, then what `more` adds.
template <class Entry>
void printRecords(const char *tag, const std::vector<Entry> &entries,
                  std::span<const ntrip::RecordField<Entry>> fields,
                  const std::function<void(JsonWriter &, const Entry &)> &more = {}) {
    for (const Entry &e : entries) {
        printJson([&](JsonWriter &w) {
            w.beginObject().field("type", tag);
            for (const auto &f : fields)
                std::visit([&](auto member) { w.field(f.name, e.*member); }, f.member);
            if (more) more(w, e);
            w.endObject();
        });
    }
}

void printTable(const ntrip::SourceTable &t, const std::optional<ntrip::GgaPosition> &from) {
    printRecords<ntrip::StreamEntry>("STR", t.streams, ntrip::streamFields(),
                                     [&](JsonWriter &w, const ntrip::StreamEntry &s) {
                                         if (const auto d = km(from, s)) w.field("distance_km", *d);
                                     });
    printRecords("CAS", t.casters, ntrip::casterFields());
    printRecords("NET", t.networks, ntrip::networkFields());
    std::string summary;
    JsonWriter w(summary);
    w.beginObject()
            .field("streams", static_cast<std::uint64_t>(t.streams.size()))
            .field("casters", static_cast<std::uint64_t>(t.casters.size()))
            .field("networks", static_cast<std::uint64_t>(t.networks.size()))
            .field("complete", t.complete)
            .field("short_records", t.shortRecords)
            .field("bad_lines", t.badLines)
            .field("long_lines", t.longLines)
            .endObject();
    std::fprintf(stderr, "%s\n", summary.c_str());
}

// Fetches the source table; nullopt (reason said) when the caster would not give it.
std::optional<ntrip::SourceTable> fetchTable(const corrections::SourceTableQuery &q) {
    corrections::SourceTableRequest request(q);
    std::optional<ntrip::SourceTable> table;
    QObject::connect(&request, &corrections::SourceTableRequest::received,
                     [&](const ntrip::SourceTable &t) {
                         table = t;
                         QCoreApplication::exit(0);
                     });
    QObject::connect(&request, &corrections::SourceTableRequest::failed, [](const QString &why) {
        say(utf8(why));
        QCoreApplication::exit(1);
    });
    request.start();
    QCoreApplication::exec();
    return table;
}

struct Options {
    QString host;
    quint16 port = 0;
    std::optional<std::string> mount;
    bool sourcetable = false;
    bool nearest = false;
    QString user, password;
    ntrip::NtripVersion version = ntrip::NtripVersion::V2;
    std::optional<ntrip::GgaPosition> position; // --gga LAT,LON,H
    std::optional<std::string> out;
    double duration = 0;
    bool quiet = false;
    std::optional<link::SourceSpec> receiver; // --port, --tcp or --sim: corrections go there
};

void writeForwarderJson(JsonWriter &w, const corrections::ForwarderStats &s) {
    w.beginObject();
    w.field("frames_forwarded", s.framesForwarded);
    w.field("bytes_forwarded", s.bytesForwarded);
    w.field("frames_dropped", s.framesDropped);
    w.field("bytes_dropped", s.bytesDropped);
    w.field("bytes_not_rtcm", s.bytesSkipped);
    w.field("crc_failures", s.crcFailures);
    w.endObject();
}

// Reads the options; false (with the reason said) when they do not make a command.
bool readOptions(const Args &args, Options &o) {
    if (!args.error().empty()) return say(args.error()), false;
    if (args.option("port") || args.option("tcp") || args.option("sim")) {
        std::string error;
        o.receiver = sourceFromArgs(args,
                                    {link::SourceSpec::Kind::Serial, link::SourceSpec::Kind::Tcp,
                                     link::SourceSpec::Kind::Simulator},
                                    error);
        if (!o.receiver) return say("ntrip: " + error), false;
    }
    const auto caster = args.option("caster");
    // "user:password@caster:2101" (or a URL with them): refused without being repeated, as the
    // password would then be in the shell's history and in `ps` for everyone to read.
    if (caster && ntrip::hasUserInfo(*caster))
        return say("ntrip: --caster takes HOST:PORT only; give the user name with --user and the "
                   "password with --password-env (what was given is not repeated: it holds a "
                   "user name or password)"),
               false;
    if (!caster ||
        !link::TcpTransport::parseHostPort(QString::fromStdString(*caster), o.host, o.port))
        return say("ntrip needs --caster HOST:PORT"), false;
    o.mount = args.option("mount");
    o.sourcetable = args.flag("sourcetable");
    o.nearest = args.flag("nearest");
    if ((o.mount ? 1 : 0) + (o.sourcetable ? 1 : 0) + (o.nearest ? 1 : 0) != 1)
        return say("ntrip: give one of --mount M, --sourcetable or --nearest"), false;
    if (const auto u = args.option("user")) o.user = QString::fromStdString(*u);
    if (const auto var = args.option("password-env")) {
        const char *pw = std::getenv(var->c_str());
        if (!pw) return say("ntrip: environment variable " + *var + " is not set"), false;
        o.password = QString::fromLocal8Bit(pw);
    }
    if (const auto v = args.option("ntrip-version")) {
        if (*v != "1" && *v != "2") return say("ntrip: --ntrip-version is 1 or 2"), false;
        o.version = *v == "1" ? ntrip::NtripVersion::V1 : ntrip::NtripVersion::V2;
    }
    const std::string gga = args.option("gga").value_or("auto");
    if (gga != "auto") {
        o.position = parsePosition(gga);
        if (!o.position)
            return say("ntrip: --gga expects auto or LAT,LON,H (degrees, metres), got '" + gga +
                       "'"),
                   false;
    }
    if (o.nearest && !o.position)
        return say("ntrip: --nearest needs the rover's position: --gga LAT,LON,H"), false;
    o.out = args.option("out");
    if (const auto d = args.option("duration")) {
        bool ok = false;
        o.duration = QString::fromStdString(*d).toDouble(&ok);
        if (!ok || o.duration < 0) return say("ntrip: --duration expects seconds >= 0"), false;
    }
    o.quiet = args.flag("quiet");
    return true;
}

int receive(const CliContext &ctx, const Options &o, const QString &mount,
            std::optional<bool> wantsGga) {
    corrections::NtripSettings s;
    s.host = o.host;
    s.port = o.port;
    s.mountpoint = mount;
    s.user = o.user;
    s.password = o.password;
    s.version = o.version;
    corrections::NtripSource source(s);
    source.setMountpointWantsGga(wantsGga);
    if (o.position)
        source.setRoverPosition(*o.position);
    else if (wantsGga.value_or(false) && !o.receiver)
        say("note: " + mount.toStdString() +
            " wants the rover's GGA; with --gga auto none is sent until forwarding to a "
            "receiver gives a fix (use --gga LAT,LON,H)");

    // Where the corrections go. A receiver (--port/--tcp) will be one more sink here.
    std::vector<std::function<void(const QByteArray &)>> sinks;
    std::FILE *file = nullptr;
    if (o.out) {
        file = std::fopen(o.out->c_str(), "wb");
        if (!file) return say("cannot write " + *o.out), 1;
        sinks.push_back([file](const QByteArray &b) {
            std::fwrite(b.constData(), 1, std::size_t(b.size()), file);
            std::fflush(file);
        });
    }
    // The receiver: corrections forwarded through its link, its epochs printed, its fix sent
    // up as the GGA (--gga auto).
    std::unique_ptr<link::Connection> receiver;
    std::unique_ptr<corrections::CorrectionForwarder> forwarder;
    EpochAssembler assembler(nullptr);
    auto onEpoch = [&](const Epoch &e) {
        if (const auto p = corrections::ggaPositionOf(e); p && !o.position)
            source.setRoverPosition(*p);
        if (o.quiet) return;
        printJson([&](JsonWriter &w) { e.writeJson(w); });
    };
    if (o.receiver) {
        OpenOptions open;
        QString why;
        receiver = openConnection(ctx, *o.receiver, open, why);
        if (!receiver) return say("cannot open the receiver: " + utf8(why)), 1;
        forwarder = std::make_unique<corrections::CorrectionForwarder>(receiver->transport(),
                                                                       receiver->commands());
        link::Connection *c = receiver.get();
        QObject::connect(c->stream(), &link::SentenceStream::sentenceDecoded,
                         [&, c](const SentenceEvent &ev) {
                             if (!ev.message) return;
                             assembler.setDialect(c->stream()->dialect());
                             assembler.add(ev.sentence, *ev.message, onEpoch);
                         });
        QObject::connect(c, &link::Connection::linkLost, [](const QString &why, int retryMs) {
            say("receiver link lost: " + utf8(why) + "; trying again in " +
                std::to_string(retryMs / 1000.0).substr(0, 3) + " s");
        });
        sinks.push_back([&forwarder](const QByteArray &b) { forwarder->feed(b); });
    }
    rtcm::RtcmStreamDecoder decoder;
    const bool json = !o.quiet && !o.receiver;
    sinks.push_back([&decoder, json](const QByteArray &b) {
        decoder.feed(std::string_view(b.constData(), std::size_t(b.size())),
                     [json](const rtcm::RtcmMessage &m) {
                         if (!json) return;
                         printJson([&](JsonWriter &w) { rtcm::writeRtcmJson(w, m); });
                     });
    });
    QObject::connect(&source, &corrections::CorrectionSource::dataReceived,
                     [&sinks](const QByteArray &b) {
                         for (auto &sink : sinks) sink(b);
                     });
    QObject::connect(&source, &corrections::CorrectionSource::stateChanged,
                     [&source](corrections::CorrectionSource::State st) {
                         using St = corrections::CorrectionSource::State;
                         if (st == St::Receiving || st == St::WaitingToRetry)
                             say(utf8(source.statusText()));
                         if (st == St::Failed) {
                             say(utf8(source.statusText()));
                             // An unknown mountpoint is a wrong request (2), nothing received.
                             QCoreApplication::exit(source.failedOnRequest() ? 2 : 1);
                         }
                     });
    if (o.duration > 0)
        QTimer::singleShot(static_cast<int>(o.duration * 1000), [] { QCoreApplication::exit(0); });
    source.start();
    int rc = source.state() != corrections::CorrectionSource::State::Failed
                     ? QCoreApplication::exec()
                     : (source.failedOnRequest() ? 2 : 1);
    source.stop();
    if (file) std::fclose(file);
    std::string summary;
    JsonWriter w(summary);
    rtcm::writeRtcmSummaryJson(w, decoder);
    std::fprintf(stderr, "%s\n", summary.c_str());
    if (forwarder) {
        std::string f;
        JsonWriter fw(f);
        writeForwarderJson(fw, forwarder->stats());
        std::fprintf(stderr, "%s\n", f.c_str());
    }
    if (rc == 0 && source.bytesReceived() == 0) {
        say("no RTCM received from " + utf8(source.description()) + " in " +
            std::to_string(static_cast<int>(o.duration)) + " s");
        rc = 1;
    }
    return rc;
}

} // namespace

int cmdNtrip(const CliContext &ctx) {
    const Args &args = ctx.args;
    Options o;
    if (!readOptions(args, o)) return 2;
    EventLoop loop;

    if (o.mount) return receive(ctx, o, QString::fromStdString(*o.mount), std::nullopt);

    corrections::SourceTableQuery q;
    q.host = o.host;
    q.port = o.port;
    q.version = o.version;
    q.user = o.user;
    q.password = o.password;
    const auto table = fetchTable(q);
    if (!table) return EventLoop::interruptedStatus() ? EventLoop::interruptedStatus() : 1;
    if (o.sourcetable) {
        printTable(*table, o.position);
        return 0;
    }
    const ntrip::NearestChoice c =
            ntrip::nearestMountpoint(*table, o.position->latDeg, o.position->lonDeg);
    if (!c.entry) {
        say("no RTCM 3 mountpoint with a position in the source table of " + utf8(o.host) + ":" +
            std::to_string(o.port));
        return 1;
    }
    char km[32];
    std::snprintf(km, sizeof km, "%.1f", c.distanceMetres / 1000.0);
    say("nearest RTCM 3 mountpoint: " + c.entry->mountpoint + " (" + c.entry->identifier + ", " +
        km + " km)");
    return receive(ctx, o, QString::fromStdString(c.entry->mountpoint), c.entry->wantsGga);
}

} // namespace gnss::cli
