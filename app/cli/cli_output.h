#pragma once
// Output helpers shared by gnss-cli's commands that run an event loop: one JSON line on standard
// output, flushed at once (a pipe reader sees each record as it happens), and QString → UTF-8.
#include "core/json_writer.h"

#include <QString>

#include <cstdio>
#include <optional>
#include <string>

namespace gnss::cli {

inline void printLine(const std::string &s) {
    std::fwrite(s.data(), 1, s.size(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

// One JSON line, as `write` writes it.
template <class Write> void printJson(Write &&write) {
    std::string out;
    JsonWriter w(out);
    write(w);
    printLine(out);
}

inline std::string utf8(const QString &s) {
    return s.toStdString();
}

// A text for a JSON field that is null when the text is empty.
inline std::optional<std::string> textOrNull(const std::string &s) {
    return s.empty() ? std::nullopt : std::optional<std::string>(s);
}
inline std::optional<std::string> textOrNull(const QString &s) {
    return textOrNull(utf8(s));
}

} // namespace gnss::cli
