#include "config/setting_values.h"

#include "core/setting_command.h"

#include "core/field_parse.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gnss::config {

namespace {

std::vector<std::string> tokens(std::string_view v) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : v) {
        if (c == ';' || c == ',' || c == ':') {
            out.push_back(trimmed(cur));
            cur.clear();
        } else {
            cur.push_back(c);
        }
    }
    out.push_back(trimmed(cur));
    // A trailing empty item (a list ending in ';') carries nothing.
    while (!out.empty() && out.back().empty()) out.pop_back();
    return out;
}

int decimalsOf(std::string_view s) {
    const auto dot = s.find('.');
    if (dot == std::string_view::npos) return 0;
    int n = 0;
    for (std::size_t i = dot + 1; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i) ++n;
    return n;
}

std::string lower(std::string_view s) {
    std::string r(s);
    for (char &c : r)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return r;
}

int boolOf(std::string_view v) {
    const std::string l = lower(trimmed(v));
    if (l == "1" || l == "on" || l == "true" || l == "yes") return 1;
    if (l == "0" || l == "off" || l == "false" || l == "no") return 0;
    return -1;
}

bool sameToken(std::string_view wanted, std::string_view reported) {
    double a, b;
    if (parseReal(wanted, a) && parseReal(reported, b)) {
        // Within half a unit of the last digit the receiver printed (it may round).
        const double tolerance =
                std::max(0.5 * std::pow(10.0, -decimalsOf(reported)), 1e-12 * std::fabs(a));
        return std::fabs(a - b) <= tolerance;
    }
    return lower(wanted) == lower(reported);
}

} // namespace

std::string trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return std::string(s);
}

bool sameValue(const SettingDef &def, std::string_view wanted, std::string_view reported) {
    if (def.type == SettingType::Bool) {
        const int a = boolOf(wanted), b = boolOf(reported);
        if (a >= 0 && b >= 0) return a == b;
    }
    const auto x = tokens(wanted), y = tokens(reported);
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (!sameToken(x[i], y[i])) return false;
    return true;
}

bool isAction(const SettingDef &def) {
    return def.key.starts_with("action.");
}

bool isReadable(const SettingDef &def) {
    return !isAction(def) && def.access != SettingAccess::WriteOnly && def.command &&
           def.command->read;
}

bool isWritable(const SettingDef &def) {
    return !isAction(def) && def.access != SettingAccess::ReadOnly && def.command &&
           def.command->write;
}

} // namespace gnss::config
