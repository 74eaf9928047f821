#pragma once
// Command-line arguments for gnss-cli: options (--name value / --flag) and positionals.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::cli {

class Args {
public:
    // `flags` are options that take no value; every other --option takes one.
    Args(int argc, char **argv, int first, std::vector<std::string_view> flags);

    bool flag(std::string_view name) const;
    std::optional<std::string> option(std::string_view name) const;
    std::vector<std::string> options(std::string_view name) const; // repeated option
    const std::vector<std::string> &positionals() const { return positionals_; }
    const std::string &error() const { return error_; }

private:
    std::vector<std::pair<std::string, std::string>> options_;
    std::vector<std::string> flags_;
    std::vector<std::string> positionals_;
    std::string error_;
};

} // namespace gnss::cli
