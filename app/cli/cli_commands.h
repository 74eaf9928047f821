#pragma once
// gnss-cli subcommands. Each is a function from its parsed arguments to an exit code;
// command_table.cpp names them, with the options each takes and its help.
#include "builtin/dialects.h"
#include "cli/cli_args.h"

#include <string_view>

namespace gnss::link {
class TransportFactory;
}

namespace gnss::cli {

struct CliContext {
    const DialectRegistry &registry;
    const Args &args; // parsed against the command's options; no error, no --help
    // The sources the link commands can open (serial, TCP, replay, the simulator).
    const link::TransportFactory *transports = nullptr;
};

int cmdDecode(const CliContext &ctx);
int cmdEpochs(const CliContext &ctx);
int cmdStats(const CliContext &ctx);
// The log viewer's engine (cmd_export.cpp, cmd_summary.cpp, cmd_play.cpp).
int cmdExport(const CliContext &ctx);
int cmdSummary(const CliContext &ctx);
int cmdPlay(const CliContext &ctx);
int cmdSchema(const CliContext &ctx);
int cmdEncode(const CliContext &ctx);
// Link commands (cmd_link.cpp): live receivers over serial/TCP, replay, recording.
int cmdPorts(const CliContext &ctx);
int cmdProbe(const CliContext &ctx);
int cmdMonitor(const CliContext &ctx);
int cmdRecord(const CliContext &ctx);
int cmdSend(const CliContext &ctx);
// Receiver settings (cmd_config.cpp): get, set, export, apply, diff.
int cmdConfig(const CliContext &ctx);
// RTCM 3 streams (cmd_rtcm.cpp): one JSON object per message, counts on standard error.
int cmdRtcm(const CliContext &ctx);
// NTRIP casters (cmd_ntrip.cpp): the source table, or a mountpoint's RTCM as JSON and/or a file.
int cmdNtrip(const CliContext &ctx);
int cmdCompare(const CliContext &ctx);
// A source's stream served (cmd_serve.cpp): an NTRIP caster of its RTCM, a raw TCP port.
int cmdServe(const CliContext &ctx);
// A time-to-first-fix campaign on a live receiver (cmd_ttff.cpp).
int cmdTtff(const CliContext &ctx);
// The user's site list (cmd_sites.cpp): list, add, remove, export, import.
int cmdSites(const CliContext &ctx);
int cmdBase(const CliContext &ctx);

} // namespace gnss::cli
