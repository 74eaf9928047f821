#pragma once
// Files for the log viewer's tests, written by the tests into a temporary folder.
#include "dialects.h"
#include "log_view.h"

#include <QString>
#include <QTemporaryDir>
#include <QTest>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

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

// For a test's hook on the viewer's worker thread: waits up to a minute for `flag` (set by the
// other side); its value at the end.
inline bool waitForFlag(const std::atomic<bool> &flag) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!flag && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return flag.load();
}

} // namespace gnss::test
