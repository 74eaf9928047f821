#pragma once
// The commands gnss-cli knows: name, function, the options it takes and its help text, in one
// table so that parsing, `gnss-cli help COMMAND` and the overview cannot disagree.
#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "sim/simulator_table.h"

#include <span>
#include <string>
#include <string_view>

namespace gnss::cli {

struct CommandSpec {
    std::string_view name;
    int (*run)(const CliContext &);
    std::string_view synopsis; // what follows "gnss-cli "; one line per form
    std::string_view summary;  // one line for the overview
    std::span<const OptionSpec> options;
    // What it reads and prints, and its exit status; "{detection order}" stands for the rates
    // baud detection tries (core/baud_rates.h).
    std::string_view details;
    // The most positional arguments it takes (-1: the command checks them itself); more are a
    // usage error, said before anything is opened.
    int maxArguments = -1;
};

std::span<const CommandSpec> commandTable();
const CommandSpec *findCommand(std::string_view name);

// `gnss-cli --help`: every command's synopsis and summary, the registry's dialects, and the
// conventions they share.
std::string overviewHelp(const DialectRegistry &registry);
// `gnss-cli help COMMAND`, `gnss-cli COMMAND --help` (with the dialects where it takes one).
std::string commandHelp(const CommandSpec &command, const DialectRegistry &registry);

// `gnss-cli --list-dialects`: a line per dialect of `registry`, "ID\tsim\tNAME" when
// `simulators` plays it, else "ID\t-\tNAME" (for shell completion and the manual pages).
std::string dialectList(const DialectRegistry &registry, const sim::SimulatorTable &simulators);

// gnss-cli itself, over `registry` and `simulators` (the built-in ones, or more: a program that
// adds a family calls this with its own); --version prints `programVersion`. Returns the exit
// status.
int runCli(const DialectRegistry &registry, const sim::SimulatorTable &simulators,
           const char *programVersion, int argc, char **argv);

} // namespace gnss::cli
