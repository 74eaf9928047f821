// gnss-cli's entry: the command line read, the command run over the registry it is given.
#include "cli/command_table.h"
#include "common/app_transports.h"

#include <cstdio>
#include <string>
#include <string_view>

namespace {

constexpr int kExitUsage = 2;

void print(std::FILE *f, const std::string &text) {
    std::fwrite(text.data(), 1, text.size(), f);
}

int version(const char *v) {
    std::printf("gnss-cli %s\n", v);
    return 0;
}

int usageError(const std::string &message, std::string_view command = {}) {
    std::fprintf(stderr, "gnss-cli: %s\n", message.c_str());
    if (command.empty())
        std::fprintf(stderr, "Try 'gnss-cli --help'.\n");
    else
        std::fprintf(stderr, "Try 'gnss-cli help %.*s'.\n", static_cast<int>(command.size()),
                     command.data());
    return kExitUsage;
}

std::string commandNames() {
    std::string names;
    for (const auto &c : gnss::cli::commandTable()) {
        if (!names.empty()) names += ", ";
        names += c.name;
    }
    return names;
}

// gnss-cli help [COMMAND]
int help(const gnss::DialectRegistry &registry, int argc, char **argv) {
    if (argc == 2) {
        print(stdout, gnss::cli::overviewHelp(registry));
        return 0;
    }
    if (argc > 3) return usageError("help takes one command");
    if (const auto *c = gnss::cli::findCommand(argv[2])) {
        print(stdout, gnss::cli::commandHelp(*c, registry));
        return 0;
    }
    return usageError(std::string("no command '") + argv[2] + "' (commands: " + commandNames() +
                      ")");
}

} // namespace

namespace gnss::cli {

std::string dialectList(const DialectRegistry &registry, const sim::SimulatorTable &simulators) {
    std::string out;
    for (const Dialect *d : registry.dialects()) {
        out += std::string(d->id) + (simulators.has(d->id) ? "\tsim\t" : "\t-\t");
        out += std::string(d->displayName) + "\n";
    }
    return out;
}

int runCli(const DialectRegistry &registry, const sim::SimulatorTable &simulators,
           const char *programVersion, int argc, char **argv) {
    if (argc < 2) {
        print(stderr, overviewHelp(registry));
        return kExitUsage;
    }
    const std::string_view first = argv[1];
    if (first == "--help" || first == "-h") {
        print(stdout, overviewHelp(registry));
        return 0;
    }
    if (first == "--version") return version(programVersion);
    if (first == "--list-dialects") {
        print(stdout, dialectList(registry, simulators));
        return 0;
    }
    if (first == "help") return help(registry, argc, argv);
    const CommandSpec *command = findCommand(first);
    if (!command) {
        if (first.starts_with('-'))
            return usageError("unknown option " + std::string(first) +
                              " (a command comes first: " + commandNames() + ")");
        return usageError("unknown command '" + std::string(first) +
                          "' (commands: " + commandNames() + ")");
    }
    const Args args(argc, argv, 2, command->options);
    // --help and --version win over anything else wrong on the line: they are how one finds out.
    if (args.helpAsked()) {
        print(stdout, commandHelp(*command, registry));
        return 0;
    }
    if (args.versionAsked()) return version(programVersion);
    if (!args.error().empty())
        return usageError(std::string(command->name) + ": " + args.error(), command->name);
    if (command->maxArguments >= 0 &&
        args.positionals().size() > static_cast<std::size_t>(command->maxArguments))
        return usageError(std::string(command->name) + ": unexpected argument '" +
                                  args.positionals()[std::size_t(command->maxArguments)] + "'",
                          command->name);
    const link::TransportFactory transports = app::makeTransportFactory(simulators);
    return command->run(CliContext{registry, args, &transports});
}

} // namespace gnss::cli
