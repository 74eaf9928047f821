#include "cli_args.h"

#include <algorithm>

namespace gnss::cli {

Args::Args(int argc, char **argv, int first, std::vector<std::string_view> flags) {
    for (int i = first; i < argc; ++i) {
        std::string_view a = argv[i];
        if (a.size() > 2 && a.substr(0, 2) == "--") {
            std::string name(a.substr(2));
            std::string value;
            const auto eq = name.find('=');
            if (eq != std::string::npos) {
                value = name.substr(eq + 1);
                name.resize(eq);
                options_.emplace_back(name, value);
                continue;
            }
            if (std::find(flags.begin(), flags.end(), name) != flags.end()) {
                flags_.push_back(name);
                continue;
            }
            if (i + 1 >= argc) {
                error_ = "option --" + name + " needs a value";
                return;
            }
            options_.emplace_back(name, argv[++i]);
        } else {
            positionals_.emplace_back(a);
        }
    }
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
