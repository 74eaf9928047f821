#include "sim/sim_args.h"

#include "sim/receiver.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <string_view>

namespace gnss::simapp {

namespace {

// The usage text around the dialect list, which comes from the records.
const char *const kUsageHead =
        "usage: gnss-sim --dialect D [--pty [--link PATH] [--com2 [--com2-link PATH]]\n"
        "                | --tcp PORT | --stdout]\n"
        "                [--seed N] [--speed X] [--duration S] [--baud B] [--faults SPEC]\n"
        "                [--internal-base] [--start now|HH:MM:SS] [--offset E,N,U]\n"
        "                [--cn0-offset [SYS:]DB,...] [--drop SATS] [--latency MS]\n"
        "                [--noise X] [--ttff SPEC]\n"
        "       gnss-sim --rtcm-base [--base-position LAT,LON,H] [--station ID]\n"
        "                [--pty | --tcp PORT | --stdout] [--seed N] [--speed X] [--duration S]\n"
        "                [--baud B]\n"
        "       gnss-sim --help | --version | --list-dialects\n"
        "\n"
        "A simulated GNSS receiver that answers its dialect's commands.\n"
        "\n"
        "  --dialect D    the receiver, one of:\n";
const char *const kUsageTail =
        "  --pty          create a pseudo-terminal (default); its device path is the first\n"
        "                 line of standard output\n"
        "  --link PATH    keep a symbolic link at PATH to the pseudo-terminal (a new one after\n"
        "                 each hang-up that comes back); removed at the end\n"
        "  --com2         a second pseudo-terminal, the receiver's second port (the\n"
        "                 NV08C-RTK's COM2: RTCM 3 there once $PNVGRZA,2 sets protocol 7 in\n"
        "                 base mode; other receivers send nothing on it); its path is the\n"
        "                 second line of standard output\n"
        "  --com2-link PATH  a symbolic link at PATH to the second pseudo-terminal\n"
        "  --tcp PORT     listen on 127.0.0.1:PORT (one client at a time); its address is the\n"
        "                 first line of standard output\n"
        "  --stdout       write to standard output, read commands from standard input\n"
        "  --seed N       random seed (same seed, same sky and noise); default 1\n"
        "  --speed X      simulated seconds per real second, up to 1000; default 1\n"
        "  --duration S   end after S simulated seconds, whether standard input closes or\n"
        "                 not (the same log each time: --stdout --speed 1000\n"
        "                 --duration 3600 > hour.nmea writes an hour's log in 4 s)\n"
        "  --baud B       the receiver's starting baud; default: the receiver's own\n"
        "  --faults SPEC  comma-separated: badcs=P, truncate=P, binary=P (probabilities),\n"
        "                 junk=BYTES (random bytes a second, a flood),\n"
        "                 silence=D@T[/EVERY] (no output, no replies: hung),\n"
        "                 noreply=CMD[+CMD], slowreply=MS,\n"
        "                 hangup=SECONDS (the line drops, gnss-sim ends),\n"
        "                 hangup=T/DOWN[xCOUNT] (--pty or --tcp: the line drops after T s with\n"
        "                 a program on it; DOWN s later a new pseudo-terminal, or the port\n"
        "                 listens again (refused meanwhile), its path or address on a new line\n"
        "                 of standard output; COUNT times, default without end),\n"
        "                 powercut=CMD[+CMD] (the first such command cuts the power before it\n"
        "                 is carried out: off 2 s, then the settings of its flash),\n"
        "                 hangupon=CMD[+CMD][/DOWN] (--pty or --tcp: the line drops as the\n"
        "                 first such command arrives, which is carried out but not answered;\n"
        "                 DOWN s later, default 1, back as hangup=T/DOWN's; once)\n"
        "  --internal-base  an RTK rover (nvs) corrects itself from a base inside the simulator;\n"
        "                 without it, it stays autonomous until RTCM 3 frames arrive on its\n"
        "                 port (float after 3 s of corrections, fixed after 20 s)\n"
        "  --start T      the simulated receiver starts at UTC T (HH:MM:SS after 10:00:00 on\n"
        "                 2024-03-15, or the next day) or now (the host's time of day): two\n"
        "                 with the same --seed and --start now see the same sky at one UTC\n"
        "  --offset E,N,U report the position moved E east, N north, U up (metres)\n"
        "  --cn0-offset [SYS:]DB,...  add DB to every signal's C/N0, or to one\n"
        "                 constellation's (GPS:-3,GLONASS:2; G R E C J S also name them)\n"
        "  --drop SATS    never report these satellites (G05,R12,E31)\n"
        "  --latency MS   send each output MS milliseconds after the epoch it belongs to\n"
        "  --ttff SPEC    times to first fix per start: cold=60:8,warm=38:5,hot=12:2,power=3\n"
        "                 (MEAN[:SPREAD] seconds, each start drawn from a normal distribution;\n"
        "                 default power 3 s, hot 2, warm 6, cold 15; the VT002 its datasheet's\n"
        "                 12/38/60 s with 15 % spread)\n"
        "  --noise X      the share of the position and C/N0 noise reported: 1 as modelled\n"
        "                 (default), 0 the truth, so receivers of any family on one sky\n"
        "                 differ by the options above alone\n"
        "  --rtcm-base    an RTK base station instead of a receiver: RTCM 3 MSM4 for GPS (1074)\n"
        "                 and GLONASS (1084) and the position (1005) every second, 1230 every\n"
        "                 10 s\n"
        "  --base-position LAT,LON,H  the base's position (degrees, ellipsoidal metres);\n"
        "                 default 55.7512,37.6184,166.6\n"
        "  --station ID   reference station id 0..4095 (default 1)\n"
        "  -h, --help     this help\n"
        "  --version      the program's version\n"
        "  --list-dialects  a line per receiver for scripts and shell completion: its id, 'sim'\n"
        "                 and its name, separated by tabs\n"
        "\n"
        "Options take their value as --opt VALUE or --opt=VALUE. Runs until --duration, killed\n"
        "or until standard input closes (not watched when it is /dev/null: `gnss-sim --pty <\n"
        "/dev/null &` runs until killed); SIGHUP power-cycles the receiver.\n"
        "Exit status: 0 the --duration ran, standard input closed or the hangup fault, 1 the\n"
        "pseudo-terminal or port could not be opened, 2 usage error, 128 + N stopped by signal\n"
        "N (130 Ctrl-C).\n";

// "now" (the host's UTC time of day) or "HH:MM:SS[.s]": seconds after 10:00:00 UTC, the
// simulation's own start, on the same day or the next.
bool startTime(std::string_view text, double &after) {
    double sod = 0;
    if (text == "now") {
        timespec ts{};
        clock_gettime(CLOCK_REALTIME, &ts);
        sod = std::fmod(static_cast<double>(ts.tv_sec) + ts.tv_nsec / 1e9, 86400.0);
    } else {
        int h = 0, m = 0;
        double sec = 0;
        char rest = 0;
        const std::string t(text);
        if (std::sscanf(t.c_str(), "%2d:%2d:%lf%c", &h, &m, &sec, &rest) != 3 || h < 0 || h > 23 ||
            m < 0 || m > 59 || sec < 0 || sec >= 60)
            return false;
        sod = h * 3600.0 + m * 60.0 + sec;
    }
    after = std::fmod(sod - sim::Receiver::kStartSecondOfDay + 86400.0, 86400.0);
    return true;
}

template <class T> bool number(std::string_view s, T &out) {
    const char *end = s.data() + s.size();
    auto [p, ec] = std::from_chars(s.data(), end, out);
    return ec == std::errc() && p == end;
}

// "LAT,LON,H": a place on Earth.
bool position(std::string_view s, sim::BaseStationConfig &base) {
    double v[3];
    for (int i = 0; i < 3; ++i) {
        const auto comma = s.find(',');
        if ((i < 2) != (comma != std::string_view::npos)) return false;
        if (!number(s.substr(0, comma), v[i]) || !std::isfinite(v[i])) return false;
        s = i < 2 ? s.substr(comma + 1) : std::string_view();
    }
    if (std::fabs(v[0]) > 90 || std::fabs(v[1]) > 180 || std::fabs(v[2]) > 100000) return false;
    base.latDeg = v[0];
    base.lonDeg = v[1];
    base.height = v[2];
    return true;
}

} // namespace

std::string usage(const DialectRegistry &registry, const sim::SimulatorTable &simulators) {
    std::string text = kUsageHead;
    for (std::string_view id : simulators.dialects()) {
        const Dialect *d = registry.find(id);
        std::string line = "                   " + std::string(id);
        line.resize(std::max<std::size_t>(line.size() + 1, 28), ' ');
        const std::string_view what = !d ? id : d->summary.empty() ? d->displayName : d->summary;
        text += line + std::string(what) + "\n";
    }
    return text + kUsageTail;
}

bool parseSimArgs(const sim::SimulatorTable &simulators, int argc, char **argv, SimArgs &out,
                  std::string &error) {
    // The first problem is kept and parsing goes on, so a --help or --version further on still
    // wins: they are how one finds out what is wrong.
    auto fail = [&](std::string message) {
        if (error.empty()) error = std::move(message);
    };
    bool differs = false; // an option that makes a receiver report otherwise than the truth
    for (int i = 1; i < argc; ++i) {
        std::string_view a = argv[i];
        // --name=value as well as --name value.
        std::optional<std::string_view> inlineValue;
        if (a.starts_with("--")) {
            if (const auto eq = a.find('='); eq != std::string_view::npos) {
                inlineValue = a.substr(eq + 1);
                a = a.substr(0, eq);
            }
        }
        auto flag = [&] {
            if (inlineValue) fail(std::string(a) + " takes no value");
            return !inlineValue;
        };
        // A separate value never starts with "--": `--tcp --pty` is a missing value.
        auto value = [&](std::string_view &v) {
            if (inlineValue) {
                v = *inlineValue;
                return true;
            }
            if (i + 1 >= argc || std::string_view(argv[i + 1]).starts_with("--")) {
                fail(std::string(a) + " needs a value");
                return false;
            }
            v = argv[++i];
            return true;
        };
        std::string_view v;
        if (a == "--help" || a == "-h") {
            out.help = flag();
        } else if (a == "--version") {
            out.version = flag();
        } else if (a == "--list-dialects") {
            out.listDialects = flag();
        } else if (a == "--dialect") {
            if (value(v)) out.dialect = std::string(v);
        } else if (a == "--pty") {
            if (flag()) out.transport = Transport::Pty;
        } else if (a == "--link") {
            if (value(v)) out.link = std::string(v);
        } else if (a == "--com2") {
            out.com2 = flag();
        } else if (a == "--com2-link") {
            if (value(v)) out.com2Link = std::string(v), out.com2 = true;
        } else if (a == "--stdout") {
            if (flag()) out.transport = Transport::Stdout;
        } else if (a == "--tcp") {
            if (!value(v)) continue;
            if (!number(v, out.tcpPort) || out.tcpPort < 1 || out.tcpPort > 65535)
                fail("--tcp: expected a port 1..65535, got '" + std::string(v) + "'");
            out.transport = Transport::Tcp;
        } else if (a == "--seed") {
            if (value(v) && !number(v, out.options.seed))
                fail("--seed: expected an unsigned integer, got '" + std::string(v) + "'");
        } else if (a == "--duration") {
            if (value(v) &&
                (!number(v, out.duration) || !std::isfinite(out.duration) || out.duration <= 0))
                fail("--duration: expected simulated seconds > 0, got '" + std::string(v) + "'");
        } else if (a == "--speed") {
            if (value(v) && (!number(v, out.speed) || !std::isfinite(out.speed) || out.speed <= 0 ||
                             out.speed > 1000))
                fail("--speed: expected a factor > 0 and <= 1000, got '" + std::string(v) + "'");
        } else if (a == "--baud") {
            if (value(v) && (!number(v, out.options.baud) || out.options.baud < 300 ||
                             out.options.baud > 921600))
                fail("--baud: expected a speed 300..921600, got '" + std::string(v) + "'");
        } else if (a == "--internal-base") {
            if (flag()) out.options.internalBase = true;
        } else if (a == "--rtcm-base") {
            if (flag()) out.rtcmBase = true;
        } else if (a == "--base-position") {
            if (value(v) && !position(v, out.base))
                fail("--base-position: expected LAT,LON,H in degrees and metres, got '" +
                     std::string(v) + "'");
        } else if (a == "--station") {
            if (value(v) && (!number(v, out.base.stationId) || out.base.stationId > 4095))
                fail("--station: expected a station id 0..4095, got '" + std::string(v) + "'");
        } else if (a == "--offset" || a == "--cn0-offset" || a == "--drop") {
            if (!value(v)) continue;
            std::string why;
            const auto parse = a == "--offset"       ? sim::parseOffset
                               : a == "--cn0-offset" ? sim::parseCn0Offset
                                                     : sim::parseDrop;
            if (auto d = parse(v, out.options.differences, why))
                out.options.differences = *d;
            else
                fail(std::string(a) + ": " + why);
            differs = true;
        } else if (a == "--latency") {
            double ms = 0;
            if (value(v) && (!number(v, ms) || !std::isfinite(ms) || ms < 0 || ms > 60000))
                fail("--latency: expected milliseconds 0..60000, got '" + std::string(v) + "'");
            out.options.differences.latency = ms / 1000.0;
            differs = true;
        } else if (a == "--noise") {
            if (value(v) && (!number(v, out.options.noise) || !std::isfinite(out.options.noise) ||
                             out.options.noise < 0 || out.options.noise > 10))
                fail("--noise: expected a scale 0..10 (1: as modelled, 0: none), got '" +
                     std::string(v) + "'");
        } else if (a == "--start") {
            if (value(v) && !startTime(v, out.options.startAfter))
                fail("--start: expected now or a UTC time HH:MM:SS, got '" + std::string(v) + "'");
        } else if (a == "--ttff") {
            if (!value(v)) continue;
            std::string why;
            if (auto t = sim::TtffModel::parse(v, why))
                out.options.ttff = *t;
            else
                fail("--ttff: " + why);
        } else if (a == "--faults") {
            if (!value(v)) continue;
            std::string why;
            if (auto f = sim::parseFaults(v, why))
                out.options.faults = *f;
            else
                fail("--faults: " + why);
        } else {
            fail(a.starts_with('-') ? "unknown option '" + std::string(a) + "'"
                                    : "unexpected argument '" + std::string(a) + "'");
        }
    }
    if (out.help || out.version || out.listDialects) return true;
    if (!error.empty()) return false;
    out.base.seed = out.options.seed;
    if (out.transport != Transport::Pty && !out.link.empty()) {
        error = "--link names a pseudo-terminal: it goes with --pty";
        return false;
    }
    if (out.com2 && (out.transport != Transport::Pty || out.rtcmBase)) {
        error = "--com2 is a receiver's second pseudo-terminal: it goes with --dialect and --pty";
        return false;
    }
    if (out.rtcmBase) {
        if (differs) {
            error = "--offset, --cn0-offset, --drop and --latency change what a receiver "
                    "reports: they go with --dialect";
            return false;
        }
        if (!out.dialect.empty()) {
            error = "--rtcm-base is a base station, not a receiver: leave out --dialect";
            return false;
        }
        return true;
    }
    if (out.dialect.empty()) {
        error = "--dialect is required (or --rtcm-base)";
        return false;
    }
    // Standard output cannot come back once it is closed: the line that does is a pseudo-terminal
    // or a TCP port.
    if (out.transport == Transport::Stdout && out.options.faults.hangupRepeats()) {
        error = "--faults: a hang-up that comes back (hangup=T/DOWN) needs --pty or --tcp";
        return false;
    }
    if (out.transport == Transport::Stdout && !out.options.faults.hangupOn.empty()) {
        error = "--faults: hangupon (the line drops and comes back) needs --pty or --tcp";
        return false;
    }
    if (!simulators.has(out.dialect)) {
        error = "unknown dialect '" + out.dialect + "' (known:";
        for (auto d : simulators.dialects()) error += " " + std::string(d);
        error += ")";
        return false;
    }
    return true;
}

} // namespace gnss::simapp
