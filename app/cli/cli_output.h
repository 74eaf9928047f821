#pragma once
// Output helpers shared by gnss-cli's commands that run an event loop: one JSON line on standard
// output, flushed at once (a pipe reader sees each record as it happens), and QString → UTF-8.
#include <QString>

#include <cstdio>
#include <string>

namespace gnss::cli {

inline void printLine(const std::string &s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

inline std::string utf8(const QString &s) {
    return s.toStdString();
}

} // namespace gnss::cli
