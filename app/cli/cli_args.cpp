#include "cli/cli_args.h"

#include <algorithm>

namespace gnss::cli {

Args::Args(int argc, char **argv, int first, std::span<const OptionSpec> known) {
    auto find = [&](std::string_view name) -> const OptionSpec * {
        for (const OptionSpec &o : known)
            if (o.name == name) return &o;
        return nullptr;
    };
    bool optionsEnded = false;
    for (int i = first; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (optionsEnded || a == "-" || !a.starts_with('-')) {
            positionals_.emplace_back(a);
            inOrder_.emplace_back(std::string(), std::string(a));
            continue;
        }
        if (a == "--") {
            optionsEnded = true;
            continue;
        }
        if (a == "-h") {
            help_ = true;
            continue;
        }
        std::string name;
        if (!a.starts_with("--")) {
            // Short options are those a command declares ("-o"); "-x" is a typo, not a file.
            const OptionSpec *shortSpec = nullptr;
            for (const OptionSpec &o : known)
                if (a.size() == 2 && o.shortName && o.shortName == a[1]) shortSpec = &o;
            if (!shortSpec) {
                fail("unknown option " + std::string(a));
                continue;
            }
            name = std::string(shortSpec->name);
        } else {
            name = std::string(a.substr(2));
        }
        std::optional<std::string> inlineValue;
        if (const auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name.resize(eq);
        }
        if (name == "help" || name == "version") {
            if (inlineValue) fail("option --" + name + " takes no value");
            (name == "help" ? help_ : version_) = true;
            continue;
        }
        const OptionSpec *spec = find(name);
        if (!spec) {
            fail("unknown option --" + name);
            continue;
        }
        if (spec->value.empty()) {
            if (inlineValue)
                fail("option --" + name + " takes no value");
            else
                flags_.push_back(name);
            continue;
        }
        if (inlineValue) {
            options_.emplace_back(name, *inlineValue);
            inOrder_.push_back(options_.back());
        } else if (i + 1 < argc && !std::string_view(argv[i + 1]).starts_with("--")) {
            options_.emplace_back(name, argv[++i]);
            inOrder_.push_back(options_.back());
        } else {
            fail("option --" + name + " needs a value (--" + name + " " + std::string(spec->value) +
                 ")");
        }
    }
}

void Args::fail(std::string message) {
    if (error_.empty()) error_ = std::move(message);
}

bool Args::flag(std::string_view name) const {
    return std::find(flags_.begin(), flags_.end(), name) != flags_.end();
}

std::optional<std::string> Args::option(std::string_view name) const {
    for (auto it = options_.rbegin(); it != options_.rend(); ++it)
        if (it->first == name) return it->second;
    return std::nullopt;
}

std::vector<std::string> Args::options(std::string_view name) const {
    std::vector<std::string> out;
    for (const auto &[k, v] : options_)
        if (k == name) out.push_back(v);
    return out;
}

} // namespace gnss::cli
