#pragma once
// gnss-cli subcommands. Each is a function from arguments to an exit code; main() holds the
// table that names them.
#include "dialects.h"

#include <string_view>

namespace gnss::cli {

struct CliContext {
    const DialectRegistry &registry;
};

int cmdDecode(const CliContext &ctx, int argc, char **argv);
int cmdEpochs(const CliContext &ctx, int argc, char **argv);
int cmdStats(const CliContext &ctx, int argc, char **argv);
int cmdSchema(const CliContext &ctx, int argc, char **argv);
int cmdEncode(const CliContext &ctx, int argc, char **argv);

} // namespace gnss::cli
