#include "link/recording_name.h"

#include <algorithm>
#include <cctype>

namespace gnss::link {

std::string recordingFileName(std::string_view name, std::vector<std::string> &taken) {
    std::string base;
    for (const char c : name) {
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')
            base += c;
        else if (!base.empty() && base.back() != '_')
            base += '_';
    }
    while (!base.empty() && (base.front() == '_' || base.front() == '.')) base.erase(0, 1);
    if (base.empty()) base = "receiver";
    std::string file = base + ".nmea";
    for (int n = 2; std::find(taken.begin(), taken.end(), file) != taken.end(); ++n)
        file = base + "-" + std::to_string(n) + ".nmea";
    taken.push_back(file);
    return file;
}

} // namespace gnss::link
