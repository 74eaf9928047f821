#pragma once
// Command-line arguments for gnss-cli: options (--name VALUE, --name=VALUE, --flag) and
// positionals, checked against the options a command declares (command_table.cpp).
//
// Every command also takes --help (-h) and --version, whatever it declares, so neither can be
// mistaken for an option's value or refused as unknown. A separate value never starts with "--"
// (`--port --help` is a missing value, not a port named "--help"); `--name=--x` passes one that
// does. "--" ends the options: what follows is positional, even "-h".
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::cli {

// One option a command accepts. `value` names what it takes (shown in the help: "--port P");
// empty for a flag. `help` is its line in `gnss-cli help COMMAND`.
struct OptionSpec {
    std::string_view name;
    std::string_view value;
    std::string_view help;
    char shortName = 0; // "-o" for --out where a command takes it; 0: none
};

class Args {
public:
    Args(int argc, char **argv, int first, std::span<const OptionSpec> known);

    bool helpAsked() const { return help_; }
    bool versionAsked() const { return version_; }
    bool flag(std::string_view name) const;
    std::optional<std::string> option(std::string_view name) const; // the last one given
    std::vector<std::string> options(std::string_view name) const;  // repeated option
    const std::vector<std::string> &positionals() const { return positionals_; }
    // Options with values and positionals as given, in their order (a positional's name is
    // empty): for commands whose repeated sources keep the order they were given in.
    const std::vector<std::pair<std::string, std::string>> &inOrder() const { return inOrder_; }
    // The first thing wrong with the command line; empty when nothing is. Parsing goes on after
    // it, so a --help further on is still seen.
    const std::string &error() const { return error_; }

private:
    void fail(std::string message);

    std::vector<std::pair<std::string, std::string>> options_;
    std::vector<std::string> flags_;
    std::vector<std::string> positionals_;
    std::vector<std::pair<std::string, std::string>> inOrder_;
    std::string error_;
    bool help_ = false;
    bool version_ = false;
};

} // namespace gnss::cli
