#include "sim_args.h"

#include <charconv>
#include <cmath>
#include <string_view>

namespace gnss::simapp {

const char *const kUsage =
        "usage: gnss-sim --dialect nvs|geostar|nemerix|nmea [--pty | --tcp PORT | --stdout]\n"
        "                [--seed N] [--speed X] [--baud B] [--faults SPEC]\n"
        "\n"
        "  --pty       create a pseudo-terminal; its device path is the first line of stdout\n"
        "  --tcp PORT  listen on 127.0.0.1:PORT (one client at a time)\n"
        "  --stdout    write to stdout, read commands from stdin\n"
        "  --seed N    random seed (same seed, same sky and noise); default 1\n"
        "  --speed X   simulated seconds per real second; default 1\n"
        "  --baud B    the receiver's starting baud; default: the receiver's own\n"
        "  --faults    badcs=P,truncate=P,binary=P,silence=D@T[/EVERY],noreply=CMD[+CMD],\n"
        "              slowreply=MS,hangup=SECONDS\n"
        "Runs until killed or until standard input closes.\n";

namespace {

template <class T> bool number(std::string_view s, T &out) {
    const char *end = s.data() + s.size();
    auto [p, ec] = std::from_chars(s.data(), end, out);
    return ec == std::errc() && p == end;
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
    if (out.dialect.empty()) {
        error = "--dialect is required";
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
