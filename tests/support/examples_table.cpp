#include "examples_table.h"

#include <fstream>
#include <sstream>

namespace gnss::test {

std::string sharedDir() {
    return GNSS_SHARED_DIR;
}

std::vector<SpecExample> loadSpecExamples() {
    std::vector<SpecExample> out;
    std::ifstream in(sharedDir() + "/specs/examples.tsv");
    if (!in) return out;
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::vector<std::string> cols;
        std::stringstream ss(line);
        std::string c;
        while (std::getline(ss, c, '\t')) cols.push_back(c);
        while (cols.size() < 6) cols.emplace_back();
        out.push_back({cols[0], cols[1], cols[2], cols[3], cols[4], cols[5]});
    }
    return out;
}

} // namespace gnss::test
