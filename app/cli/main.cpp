// gnss-cli: headless GNSS Workbench. See docs/cli.md; the commands are in command_table.cpp.
#include "command_table.h"
#include "dialects.h"

int main(int argc, char **argv) {
    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    return gnss::cli::runCli(registry, GNSS_VERSION, argc, argv);
}
