// gnss-cli: headless GNSS Workbench. See docs/cli.md.
#include "app_transports.h"
#include "cli_commands.h"

#include <cstdio>
#include <cstring>
#include <string_view>

namespace {

struct Command {
    std::string_view name;
    int (*run)(const gnss::cli::CliContext &, int, char **);
    std::string_view synopsis;
};

constexpr Command kCommands[] = {
        {"decode", gnss::cli::cmdDecode,
         "decode [--dialect D] [--lenient] [FILE|-]   one JSON object per sentence"},
        {"epochs", gnss::cli::cmdEpochs,
         "epochs [--dialect D] [--lenient] [FILE|-]   one JSON object per navigation epoch"},
        {"stats", gnss::cli::cmdStats,
         "stats [--dialect D] [--lenient] [--json] [FILE|-]   vet a log: counts per address"},
        {"schema", gnss::cli::cmdSchema, "schema DIALECT   the dialect's settings schema as JSON"},
        {"encode", gnss::cli::cmdEncode,
         "encode DIALECT KEY=VALUE... | encode DIALECT --query KEY...   sentences to send"},
        {"ports", gnss::cli::cmdPorts, "ports   serial ports, one JSON object each"},
        {"probe", gnss::cli::cmdProbe,
         "probe --port P [--baud B]   detect baud, dialect, model and firmware (JSON)"},
        {"monitor", gnss::cli::cmdMonitor,
         "monitor --port P|--tcp H:P|--replay FILE [--epochs] [--duration S]   live decode"},
        {"record", gnss::cli::cmdRecord,
         "record --port P|--tcp H:P --out FILE [--duration S]   FILE + FILE.idx"},
        {"send", gnss::cli::cmdSend,
         "send --port P|--tcp H:P [--baud B] SENTENCE...   replies and outcome per command"},
        {"config", gnss::cli::cmdConfig,
         "config --port P [--baud B] | --sim D  get [KEY...] | set KEY=VALUE... | export FILE | "
         "apply FILE | diff FILE | action save|defaults|cold|warm|hot"},
        {"rtcm", gnss::cli::cmdRtcm,
         "rtcm [FILE|-]   one JSON object per RTCM 3 message; counts on stderr"},
        {"ntrip", gnss::cli::cmdNtrip,
         "ntrip --caster H:P --mount M|--sourcetable|--nearest [--user U] [--password-env VAR]\n"
         "        [--ntrip-version 1|2] [--gga auto|LAT,LON,H] [--out FILE] [--duration S] "
         "[--quiet]"},
};

void usage(std::FILE *f) {
    std::fprintf(f, "usage: gnss-cli COMMAND [OPTIONS]\n\ncommands:\n");
    for (const auto &c : kCommands)
        std::fprintf(f, "  %.*s\n", static_cast<int>(c.synopsis.size()), c.synopsis.data());
    std::fprintf(
            f,
            "\nD: auto (default), nvs, geostar, nemerix, nmea\n"
            "--alias NEW=PNMRX reads a renamed prefix; with --dialect nemerix, --prefix NEW reads\n"
            "and (encode) writes it. See docs/cli.md.\n");
}

} // namespace

int main(int argc, char **argv) {
    if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    const gnss::link::TransportFactory transports = gnss::app::makeTransportFactory();
    const gnss::cli::CliContext ctx{registry, &transports};
    for (const auto &c : kCommands)
        if (c.name == argv[1]) return c.run(ctx, argc, argv);
    std::fprintf(stderr, "gnss-cli: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return 2;
}
