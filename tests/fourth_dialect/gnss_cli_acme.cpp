// gnss-cli with the test-only ACME family registered beside the built-in ones (acme_registry.h):
// the same program as gnss-cli but for those lines.
#include "acme_registry.h"
#include "cli/command_table.h"

int main(int argc, char **argv) {
    const gnss::DialectRegistry registry = gnss::acme::registryWithAcme();
    const gnss::sim::SimulatorTable simulators = gnss::acme::simulatorsWithAcme();
    return gnss::cli::runCli(registry, simulators, "test", argc, argv);
}
