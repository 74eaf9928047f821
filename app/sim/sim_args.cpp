#include "sim_args.h"

#include <charconv>
#include <cmath>
#include <string_view>

namespace gnss::simapp {

const char *const kUsage =
        "usage: gnss-sim --dialect nvs|geostar|nemerix|nmea [--pty | --tcp PORT | --stdout]\n"
        "                [--seed N] [--speed X] [--baud B] [--faults SPEC]\n"
        "       gnss-sim --rtcm-base [--base-position LAT,LON,H] [--station ID]\n"
        "                [--pty | --tcp PORT | --stdout] [--seed N] [--speed X] [--baud B]\n"
        "\n"
        "  --pty       create a pseudo-terminal; its device path is the first line of stdout\n"
        "  --tcp PORT  listen on 127.0.0.1:PORT (one client at a time)\n"
        "  --stdout    write to stdout, read commands from stdin\n"
        "  --seed N    random seed (same seed, same sky and noise); default 1\n"
        "  --speed X   simulated seconds per real second; default 1\n"
        "  --baud B    the receiver's starting baud; default: the receiver's own\n"
        "  --faults    badcs=P,truncate=P,binary=P,silence=D@T[/EVERY],noreply=CMD[+CMD],\n"
        "              slowreply=MS,hangup=SECONDS\n"
        "  --rtcm-base an RTK base station instead of a receiver: RTCM 3 MSM4 for GPS (1074)\n"
        "              and GLONASS (1084) and the position (1005) every second, 1230 every 10 s\n"
        "  --base-position LAT,LON,H  the base's position (degrees, ellipsoidal metres);\n"
        "              default 55.7512,37.6184,166.6\n"
        "  --station ID  reference station id 0..4095 (default 1)\n"
        "Runs until killed or until standard input closes.\n";

namespace {

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

bool parseSimArgs(int argc, char **argv, SimArgs &out, std::string &error, bool &help) {
    help = false;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        auto value = [&](std::string_view &v) {
            if (i + 1 >= argc) {
                error = std::string(a) + " needs a value";
                return false;
            }
            v = argv[++i];
            return true;
        };
        std::string_view v;
        if (a == "--help" || a == "-h") {
            help = true;
            return true;
        } else if (a == "--dialect") {
            if (!value(v)) return false;
            out.dialect = std::string(v);
        } else if (a == "--pty") {
            out.transport = Transport::Pty;
        } else if (a == "--stdout") {
            out.transport = Transport::Stdout;
        } else if (a == "--tcp") {
            if (!value(v)) return false;
            if (!number(v, out.tcpPort) || out.tcpPort < 1 || out.tcpPort > 65535) {
                error = "--tcp: expected a port 1..65535, got '" + std::string(v) + "'";
                return false;
            }
            out.transport = Transport::Tcp;
        } else if (a == "--seed") {
            if (!value(v)) return false;
            if (!number(v, out.options.seed)) {
                error = "--seed: expected an unsigned integer, got '" + std::string(v) + "'";
                return false;
            }
        } else if (a == "--speed") {
            if (!value(v)) return false;
            if (!number(v, out.speed) || !std::isfinite(out.speed) || out.speed <= 0 ||
                out.speed > 1000) {
                error = "--speed: expected a factor > 0 and <= 1000, got '" + std::string(v) + "'";
                return false;
            }
        } else if (a == "--baud") {
            if (!value(v)) return false;
            if (!number(v, out.options.baud) || out.options.baud < 300 ||
                out.options.baud > 921600) {
                error = "--baud: expected a speed 300..921600, got '" + std::string(v) + "'";
                return false;
            }
        } else if (a == "--rtcm-base") {
            out.rtcmBase = true;
        } else if (a == "--base-position") {
            if (!value(v)) return false;
            if (!position(v, out.base)) {
                error = "--base-position: expected LAT,LON,H in degrees and metres, got '" +
                        std::string(v) + "'";
                return false;
            }
        } else if (a == "--station") {
            if (!value(v)) return false;
            if (!number(v, out.base.stationId) || out.base.stationId > 4095) {
                error = "--station: expected a station id 0..4095, got '" + std::string(v) + "'";
                return false;
            }
        } else if (a == "--faults") {
            if (!value(v)) return false;
            auto f = sim::parseFaults(v, error);
            if (!f) {
                error = "--faults: " + error;
                return false;
            }
            out.options.faults = *f;
        } else {
            error = "unknown option '" + std::string(a) + "'";
            return false;
        }
    }
    out.base.seed = out.options.seed;
    if (out.rtcmBase) {
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
    bool known = false;
    for (auto d : sim::simulatedDialects()) known = known || d == out.dialect;
    if (!known) {
        error = "unknown dialect '" + out.dialect + "' (known:";
        for (auto d : sim::simulatedDialects()) error += " " + std::string(d);
        error += ")";
        return false;
    }
    return true;
}

} // namespace gnss::simapp
