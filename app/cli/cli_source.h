#pragma once
// The source every gnss-cli link command takes, named the same way everywhere:
//   --port P [--baud B]        a serial port (without --baud: the speed is detected)
//   --tcp HOST:PORT            a serial server or remote receiver
//   --gpsd HOST[:PORT][/DEVICE]  a receiver that gpsd holds (read only: gpsd owns the port)
//   --replay FILE [--speed X] [--fast]   a recorded log
//   --sim DIALECT [--baud B]   a built-in simulated receiver
// and opened through the application's one TransportFactory, as the GUI does (LinkOpener).
// Qt Core: only the commands that need an event loop include this.
#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "link/baud_detector.h"
#include "link/command_queue.h"
#include "link/connection.h"
#include "link/source_spec.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gnss::cli {

// The source kind an option names ("port", "tcp", "gpsd", "replay", "sim"); none for others.
std::optional<link::SourceSpec::Kind> sourceKindOf(std::string_view option);
// One source from its option's value, checked as sourceFromArgs checks it (without --baud).
std::optional<link::SourceSpec> sourceSpecOf(link::SourceSpec::Kind kind, const std::string &value,
                                             std::string &error);

// The source named by the arguments; nullopt with `error` when none, several, or malformed.
// `allowed` lists the kinds the command takes (a replay cannot take commands, for instance).
std::optional<link::SourceSpec>
sourceFromArgs(const Args &args, std::initializer_list<link::SourceSpec::Kind> allowed,
               std::string &error);
// The option names of the sources, for usage texts: "--port P | --tcp H:P | ...".
std::string sourceOptionsText(std::initializer_list<link::SourceSpec::Kind> allowed);

struct OpenOptions {
    DecoderOptions decoder;
    bool waitUntilOpen = true; // return only once bytes can flow (a TCP connect, a log indexed)
    int openTimeoutMs = 15000;
    bool autoReconnect = true;
    link::BaudDetection *detection = nullptr; // out: what baud detection tried, when it ran
};

// Opens a connection to `spec` (baud detection for a serial port without a speed, each rate
// reported on standard error); nullptr with `error` set when it cannot. Needs a running
// QCoreApplication (it runs the event loop until the link is open). `refused` (when given) tells
// a request the other end refused (a device gpsd does not have: a usage error) from a source that
// failed.
std::unique_ptr<link::Connection> openConnection(const CliContext &ctx,
                                                 const link::SourceSpec &spec,
                                                 const OpenOptions &options, QString &error,
                                                 bool *refused = nullptr);

// Link events on standard error ("... trying again in 2 s" + `note`); a link that cannot be opened
// and will not be retried ends the event loop with status 1 (2 for a device gpsd lacks).
void reportLinkEvents(link::Connection &conn, const char *note);

// Several sources opened together, their speeds detected at once (messages prefixed with each
// one's name); empty with `error` set when one cannot be opened.
std::vector<std::unique_ptr<link::Connection>>
openConnections(const CliContext &ctx, const std::vector<link::SourceSpec> &specs,
                const OpenOptions &options, QString &error, bool *refused = nullptr);

// A command's result as one JSON line: sentence, outcome, detail, (with `timing`: attempts and
// ms), the replies, and the speed it switched to (when it did).
void printCommandResult(const link::CommandResult &r, bool timing);

} // namespace gnss::cli
