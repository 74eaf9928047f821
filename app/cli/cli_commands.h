#pragma once
// gnss-cli subcommands. Each is a function from arguments to an exit code; main() holds the
// table that names them.
#include "dialects.h"

#include <string_view>

namespace gnss::link {
class TransportFactory;
}

namespace gnss::cli {

struct CliContext {
    const DialectRegistry &registry;
    // The sources the link commands can open (serial, TCP, replay, the simulator).
    const link::TransportFactory *transports = nullptr;
};

int cmdDecode(const CliContext &ctx, int argc, char **argv);
int cmdEpochs(const CliContext &ctx, int argc, char **argv);
int cmdStats(const CliContext &ctx, int argc, char **argv);
int cmdSchema(const CliContext &ctx, int argc, char **argv);
int cmdEncode(const CliContext &ctx, int argc, char **argv);
// Link commands (cmd_link.cpp): live receivers over serial/TCP, replay, recording.
int cmdPorts(const CliContext &ctx, int argc, char **argv);
int cmdProbe(const CliContext &ctx, int argc, char **argv);
int cmdMonitor(const CliContext &ctx, int argc, char **argv);
int cmdRecord(const CliContext &ctx, int argc, char **argv);
int cmdSend(const CliContext &ctx, int argc, char **argv);
// Receiver settings (cmd_config.cpp): get, set, export, apply, diff.
int cmdConfig(const CliContext &ctx, int argc, char **argv);
// RTCM 3 streams (cmd_rtcm.cpp): one JSON object per message, counts on standard error.
int cmdRtcm(const CliContext &ctx, int argc, char **argv);
// NTRIP casters (cmd_ntrip.cpp): the source table, or a mountpoint's RTCM as JSON and/or a file.
int cmdNtrip(const CliContext &ctx, int argc, char **argv);

} // namespace gnss::cli
