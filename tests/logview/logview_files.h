#pragma once
// Files for the log viewer's tests, written by the tests into a temporary folder.
#include "builtin/dialects.h"
#include "logview/log_view.h"

#include <QString>
#include <QTemporaryDir>
#include <QTest>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <thread>

namespace gnss::test {

inline bool writeFile(const std::string &path, std::string_view bytes) {
    std::FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    return std::fclose(f) == 0 && ok;
}

inline std::string readFile(const std::string &path) {
    std::string out;
    std::FILE *f = std::fopen(path.c_str(), "rb");
    if (!f) return out;
    char buf[65536];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
    std::fclose(f);
    return out;
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

// Twenty epochs of `view` (the first `first`, then picked by `seed` below `end`) against the same
// epochs of `reference`: offsets, UTC and the receiver state rebuilt there. QCOMPARE inside: the
// caller returns when QTest::currentTestFailed().
inline void compareEpochs(const logview::LogView &view, const logview::LogView &reference,
                          unsigned seed, std::size_t end, std::optional<std::size_t> first = {}) {
    std::mt19937 rng(seed);
    ReceiverState a, b;
    for (int i = 0; i < 20; ++i) {
        const std::size_t k = i == 0 && first ? *first : rng() % end;
        QCOMPARE(view.epoch(k)->offset, reference.epoch(k)->offset);
        QCOMPARE(view.epoch(k)->utcMs, reference.epoch(k)->utcMs);
        QVERIFY(view.stateAt(k, a) && reference.stateAt(k, b));
        QVERIFY(a == b);
    }
}

// The whole index of `view` against `reference`'s: epochs, indexed bytes, events, sentences, and
// twenty epochs compared as above.
inline void compareIndexes(const logview::LogView &view, const logview::LogView &reference,
                           unsigned seed) {
    QCOMPARE(view.epochCount(), reference.epochCount());
    QCOMPARE(view.indexedEnd(), reference.indexedEnd());
    QCOMPARE(view.events().size(), reference.events().size());
    QCOMPARE(view.framerStats().sentences, reference.framerStats().sentences);
    compareEpochs(view, reference, seed, view.epochCount());
}

} // namespace gnss::test
