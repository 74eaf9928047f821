// Writes the schema text catalog (schema_catalog.h) of the built-in dialects to the file named
// on the command line; the update_schema_catalog target runs it before lupdate.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "schema_catalog.h"

#include <cstdio>
#include <fstream>

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT.cpp\n", argv[0]);
        return 2;
    }
    const std::vector<const gnss::Dialect *> dialects = gnss::builtinDialects();
    std::ofstream out(argv[1], std::ios::binary | std::ios::trunc);
    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    out << gnss::schemaCatalogSource(dialects, registry, gnss::sim::builtinSimulators());
    return out.good() ? 0 : 1;
}
