#pragma once
// Files for the log viewer's tests, written by the tests into a temporary folder.
#include "dialects.h"
#include "log_view.h"

#include <QString>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>
#include <string>

namespace gnss::test {

inline bool writeFile(const std::string &path, std::string_view bytes) {
    std::FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    return std::fclose(f) == 0 && ok;
}

// Opens `path` and waits for the index.
inline bool openAndWait(logview::LogView &view, const std::string &path) {
    view.open(path);
    return view.waitUntilIndexed(120000) && view.progress().phase == logview::LogView::Phase::Ready;
}

} // namespace gnss::test
