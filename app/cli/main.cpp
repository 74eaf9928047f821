// gnss-cli: headless GNSS Workbench. See docs/cli.md; the commands are in command_table.cpp.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "cli/command_table.h"

int main(int argc, char **argv) {
    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    return gnss::cli::runCli(registry, gnss::sim::builtinSimulators(), GNSS_VERSION, argc, argv);
}
