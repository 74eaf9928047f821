#pragma once
// The link and the settings engine behind the commands that change a receiver's settings
// (gnss-cli config, gnss-cli base): the source opened, its speed found and its dialect identified;
// an engine operation run to its end; an apply's commands and verification printed as JSON lines.
#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "config/settings_engine.h"
#include "link/connection.h"

#include <functional>
#include <memory>

namespace gnss::cli {

struct Link {
    std::unique_ptr<link::Connection> connection;
    const Dialect *dialect = nullptr;
    bool usageError = false; // no link because the options were wrong (exit 2, not 1)
};

// Opens the source (--port, --tcp or --sim), finds the speed and the dialect (--dialect, or
// identified); an empty Link after saying why on standard error.
Link openLink(const CliContext &ctx, const Args &args);

// Runs an engine operation to its end.
config::OperationReport runOperation(config::SettingsEngine &engine,
                                     const std::function<bool()> &start);

// A read's failure said on standard error; true when it succeeded.
bool reportRead(const config::OperationReport &r);

// The verification of an apply, one JSON line per setting, then the summary line.
void printChecks(const config::OperationReport &r);

// Runs an apply or an action, printing each command's outcome and the checks: 0 when everything
// verified, 2 when the request was refused before anything was sent, else 1.
int applyValues(config::SettingsEngine &engine, const std::function<bool()> &start);

} // namespace gnss::cli
