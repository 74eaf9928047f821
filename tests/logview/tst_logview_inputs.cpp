// Bad input is normal: the log viewer's engine opens anything without crashing, says what it
// found, and keeps what it read: empty files, random bytes, a 4096-byte line, NUL bytes, a
// truncated last line, .gz logs (whole and cut), recordings with host times, files cut or
// deleted while open, a file still being written, and offsets past 4 GB (a sparse file).
#include "logview_files.h"
#include "logview_reference.h"

#include <chrono>
#include <random>
#include <thread>

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

using namespace gnss;
using namespace gnss::logview;

class TstLogviewInputs : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    DialectRegistry registry_ = makeBuiltinRegistry();

    std::string path(const char *name) const { return dir_.filePath(name).toStdString(); }

private slots:
    // The generated log, made a piece at a time (as gnss-loggen writes logs of any size), is
    // byte for byte the log made at once, which the suites and benchmarks use.
    void theGeneratedLogInPiecesIsTheLogAtOnce() {
        std::string whole;
        bench::generateLog(whole, 3'000'000);
        bench::LogGenerator generator;
        std::string pieces, piece;
        for (std::size_t size = 1; pieces.size() < whole.size(); size = size * 3 + 7) {
            piece.clear();
            generator.append(piece, std::min<std::size_t>(size, whole.size() - pieces.size()));
            pieces += piece;
        }
        QCOMPARE(pieces.size(), whole.size());
        QVERIFY(pieces == whole);
    }

    void opensWhateverItIsGiven_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<int>("epochs");
        QTest::addColumn<QString>("warning");
        const std::string good = test::scenarioLog({});
        std::mt19937 rng(1);
        QByteArray random(200000, '\0');
        for (auto &c : random) c = static_cast<char>(rng());
        random.replace('$', 'x');
        QTest::newRow("empty") << QByteArray() << 0 << "is empty";
        QTest::newRow("random bytes") << random << 0 << "no NMEA found";
        QTest::newRow("no newline at all") << QByteArray(100000, 'A') << 0 << "no NMEA found";
        QByteArray longLine = QByteArray("$GPTXT,") + QByteArray(4096, 'x') + "\r\n";
        QTest::newRow("4096-byte line, then a log")
                << longLine + QByteArray::fromStdString(good) << 600 << "";
        QByteArray nul = QByteArray::fromStdString(good);
        for (int i = 1000; i < nul.size(); i += 5000) nul[i] = '\0';
        QTest::newRow("NUL bytes") << nul << -1 << "";
        QByteArray cut = QByteArray::fromStdString(good);
        cut.chop(20);
        QTest::newRow("truncated last line") << cut << 600 << "";
        QTest::newRow("only sentences without epochs")
                << QByteArray("$GPTXT,01,01,02,hello*00\r\n$PNVGVER*4E\r\n") << 0
                << "no navigation epoch";
    }
    void opensWhateverItIsGiven() {
        QFETCH(QByteArray, bytes);
        QFETCH(int, epochs);
        QFETCH(QString, warning);
        const std::string p = path("input.nmea");
        QVERIFY(test::writeFile(p, std::string_view(bytes.constData(), bytes.size())));
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, p));
        if (epochs >= 0) QCOMPARE(int(view.epochCount()), epochs);
        const auto truth =
                test::frontToBack(std::string_view(bytes.constData(), bytes.size()), registry_);
        QCOMPARE(view.epochCount(), truth.size());
        bool warned = warning.isEmpty();
        for (const auto &w : view.warnings()) warned |= QString::fromStdString(w).contains(warning);
        QVERIFY2(warned, qPrintable(warning));
        // Everything answers on whatever came out.
        ReceiverState s;
        if (view.epochCount()) {
            QVERIFY(view.stateAt(view.epochCount() - 1, s));
            QVERIFY(s == truth.back());
        }
        QVERIFY(!view.stateAt(view.epochCount(), s));
        view.linesAround(bytes.size() / 2, 5, 5);
        view.stats(0, view.epochCount());
        std::string out;
        QVERIFY(view.exportRange(ExportFormat::Nmea, 0, view.epochCount(), [&](std::string_view b) {
            out += b;
            return true;
        }));
        if (view.epochCount()) QCOMPARE(out.size(), std::size_t(bytes.size()));
    }

    void cannotOpenIsAnError() {
        LogView view(registry_);
        view.open(path("does-not-exist.nmea"));
        QVERIFY(view.waitUntilIndexed(10000));
        QCOMPARE(view.progress().phase, LogView::Phase::Failed);
        QVERIFY(QString::fromStdString(view.error()).contains("No such file"));
    }

    void gzipLogs_data() {
        QTest::addColumn<bool>("cut");
        QTest::newRow("whole") << false;
        QTest::newRow("cut short") << true;
    }
    void gzipLogs() {
        QFETCH(bool, cut);
        const std::string text = test::scenarioLog({});
        const std::string p = path("log.nmea");
        QVERIFY(test::writeFile(p, text));
        // Compressed here with zlib, as gzip would (no child process: under ThreadSanitizer a
        // fork from this multi-threaded test is not allowed).
        std::string gzPath = p + ".gz";
        gzFile gz = gzopen(gzPath.c_str(), "wb");
        QVERIFY(gz);
        QCOMPARE(gzwrite(gz, text.data(), unsigned(text.size())), int(text.size()));
        QCOMPARE(gzclose(gz), Z_OK);
        if (cut) QVERIFY(::truncate(gzPath.c_str(), 3000) == 0);
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, gzPath));
        QVERIFY(view.gzipped());
        if (!cut) {
            QCOMPARE(view.epochCount(), std::size_t(600));
            QCOMPARE(view.fileSize(), std::uint64_t(text.size()));
        } else {
            QVERIFY(view.epochCount() > 0 && view.epochCount() < 600);
            QVERIFY(!view.warnings().empty());
        }
        ReceiverState s;
        QVERIFY(view.stateAt(view.epochCount() / 2, s));
    }

    // A .gz log is indexed while it is inflated: the worker, held by the test's hook as soon as
    // the first epoch is known, is still inflating then (48 MB take far longer to inflate than
    // the first megabyte); the index is then the same as the plain file's.
    void gzipLogsAreIndexedWhileInflating() {
        std::string log;
        bench::generateLog(log, 48'000'000);
        const std::string plainPath = path("inflating.nmea");
        QVERIFY(test::writeFile(plainPath, log));
        const std::string gzPath = plainPath + ".gz";
        gzFile gz = gzopen(gzPath.c_str(), "wb1");
        QVERIFY(gz);
        for (std::size_t at = 0; at < log.size();) {
            const unsigned n = unsigned(std::min<std::size_t>(log.size() - at, 1 << 20));
            QCOMPARE(gzwrite(gz, log.data() + at, n), int(n));
            at += n;
        }
        QCOMPARE(gzclose(gz), Z_OK);
        std::atomic<bool> held{false}, released{false};
        LogViewOptions o;
        o.onFirstEpoch = [&] {
            held = true;
            test::waitForFlag(released);
        };
        LogView view(registry_, o);
        view.open(gzPath);
        const bool wasHeld = test::waitForFlag(held);
        const LogView::Progress p = view.progress();
        const auto first = view.firstEpoch();
        const std::uint64_t mapped = view.fileSize();
        released = true;
        QVERIFY(wasHeld);
        QCOMPARE(p.phase, LogView::Phase::Inflating);
        QVERIFY(first);
        QCOMPARE(first->offset, std::uint64_t(0));
        QVERIFY(mapped < log.size());
        qInfo("first epoch known after %.1f MB of %.1f MB inflated (%.0f %% of the .gz read)",
              double(mapped) / 1e6, double(log.size()) / 1e6, p.fraction * 100);
        QVERIFY(view.waitUntilIndexed(120000));
        QCOMPARE(view.progress().phase, LogView::Phase::Ready);
        QVERIFY(view.gzipped());
        QVERIFY(view.warnings().empty());
        LogView plain(registry_);
        QVERIFY(test::openAndWait(plain, plainPath));
        QCOMPARE(view.fileSize(), plain.fileSize());
        test::compareIndexes(view, plain, 9);
        if (QTest::currentTestFailed()) return;
        // Cancelled while inflating: it stops.
        view.open(gzPath);
        view.cancel();
        QVERIFY(view.waitUntilIndexed(60000));
        QVERIFY(view.progress().phase == LogView::Phase::Cancelled ||
                view.progress().phase == LogView::Phase::Ready);
    }

    // Cancelled part way (by the test's hook, at the first epoch), the exact start indexed is
    // kept: the same epochs and states as the whole log's, a plain log and a .gz one.
    void cancelKeepsWhatWasIndexed_data() {
        QTest::addColumn<bool>("gzipped");
        QTest::newRow("plain") << false;
        QTest::newRow(".gz") << true;
    }
    void cancelKeepsWhatWasIndexed() {
        QFETCH(bool, gzipped);
        std::string log;
        bench::generateLog(log, 48'000'000);
        std::string p = path("cancelled.nmea");
        QVERIFY(test::writeFile(p, log));
        LogView whole(registry_);
        QVERIFY(test::openAndWait(whole, p));
        if (gzipped) {
            p += ".gz";
            gzFile gz = gzopen(p.c_str(), "wb1");
            QVERIFY(gz);
            for (std::size_t at = 0; at < log.size();) {
                const unsigned n = unsigned(std::min<std::size_t>(log.size() - at, 1 << 20));
                QCOMPARE(gzwrite(gz, log.data() + at, n), int(n));
                at += n;
            }
            QCOMPARE(gzclose(gz), Z_OK);
        }
        LogView *self = nullptr;
        LogViewOptions o;
        o.onFirstEpoch = [&self] { self->cancel(); };
        LogView view(registry_, o);
        self = &view;
        view.open(p);
        QVERIFY(view.waitUntilIndexed(120000));
        QCOMPARE(view.progress().phase, LogView::Phase::Cancelled);
        const std::size_t kept = view.epochCount();
        QVERIFY2(kept > 100 && kept < whole.epochCount() / 2, qPrintable(QString::number(kept)));
        QVERIFY(!view.warnings().empty());
        QVERIFY(QString::fromStdString(view.warnings().back()).contains("indexing cancelled"));
        QVERIFY(view.indexedEnd() < log.size() / 2);
        test::compareEpochs(view, whole, 11, kept - 1, kept - 2); // the last one is open
        if (QTest::currentTestFailed()) return;
        QCOMPARE(view.epoch(0)->offset, std::uint64_t(0));
    }

    void recordingsUseTheirHostTimes() {
        const std::string text = test::scenarioLog({});
        const std::string p = path("rec.nmea");
        QVERIFY(test::writeFile(p, text));
        // One chunk per 1000 bytes, 250 ms apart; the link lost in the middle for 5 s.
        std::string idx = "# gnss-workbench recording index 1\n";
        std::int64_t ms = 1710496800000;
        for (std::size_t off = 0; off < text.size(); off += 1000) {
            const std::size_t len = std::min<std::size_t>(1000, text.size() - off);
            if (off == 60000) {
                idx += "G " + std::to_string(ms) + " 60000 link lost: test\n";
                ms += 5000;
                idx += "G " + std::to_string(ms) + " 60000 link back: test\n";
            }
            idx += "R " + std::to_string(ms) + " " + std::to_string(off) + " " +
                   std::to_string(len) + "\n";
            ms += 250;
        }
        QVERIFY(test::writeFile(p + ".idx", idx));
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, p));
        QVERIFY(view.hasHostTimes());
        const auto first = view.epoch(0), last = view.epoch(599);
        QCOMPARE(first->hostMs, std::int64_t(1710496800000));
        QVERIFY(last->hostMs > first->hostMs);
        int links = 0;
        for (const auto &e : view.events()) links += e.kind == EventKind::LinkGap;
        QCOMPARE(links, 2);
        // An index that contradicts the file is reported and not used.
        QVERIFY(test::writeFile(p + ".idx", "R 1 5 10\n"));
        LogView other(registry_);
        QVERIFY(test::openAndWait(other, p));
        QVERIFY(!other.hasHostTimes());
        QVERIFY(!other.warnings().empty());
    }

    void fileCutOrDeletedWhileOpen() {
        const std::string text = test::scenarioLog({});
        const std::string p = path("cut.nmea");
        QVERIFY(test::writeFile(p, text));
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, p));
        QVERIFY(::truncate(p.c_str(), static_cast<off_t>(text.size() / 2)) == 0);
        const auto r = view.follow();
        QVERIFY(r.truncated);
        QCOMPARE(view.epochCount(), std::size_t(600)); // what was read is kept
        ReceiverState s;
        QVERIFY(view.stateAt(10, s));   // before the cut: still there
        QVERIFY(!view.stateAt(590, s)); // past the cut: reported, no crash
        QVERIFY(view.bytes(text.size() - 10, 10).empty());
        QVERIFY(view.linesAround(text.size() - 10, 3, 3).size() <= 7);
        std::string out;
        view.exportRange(ExportFormat::Nmea, 0, 599, [&](std::string_view b) {
            out += b;
            return true;
        });
        QCOMPARE(out.size(), text.size() / 2);
        // Deleted: the mapping stays readable.
        QVERIFY(::unlink(p.c_str()) == 0);
        view.follow();
        QVERIFY(view.stateAt(5, s));
    }

    void followsAFileBeingWritten() {
        const std::string text = test::scenarioLog({});
        const std::string p = path("growing.nmea");
        const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        QVERIFY(fd >= 0);
        std::size_t written = 12345; // mid-line
        QVERIFY(::write(fd, text.data(), written) == static_cast<ssize_t>(written));
        LogView view(registry_);
        QVERIFY(test::openAndWait(view, p));
        const std::size_t before = view.epochCount();
        QVERIFY(before > 0 && before < 600);
        QVERIFY(view.lastEpochOpen());
        while (written < text.size()) {
            const std::size_t n = std::min<std::size_t>(text.size() - written, 7777);
            QVERIFY(::write(fd, text.data() + written, n) == static_cast<ssize_t>(n));
            written += n;
            const auto r = view.follow();
            QVERIFY(r.grew);
            QVERIFY(r.firstChanged <= view.epochCount());
        }
        ::close(fd);
        QCOMPARE(view.epochCount(), std::size_t(600));
        const auto truth = test::frontToBack(text, registry_);
        ReceiverState s;
        for (std::size_t k : {0, 123, 456, 599}) {
            QVERIFY(view.stateAt(k, s));
            QVERIFY(s == truth[k]);
        }
        QCOMPARE(view.events().size(), std::size_t(17));
    }

    // A big growth (19 MB) is decoded without the readers' lock: follow() on a thread is held
    // (by the test's hook) in the middle of its decoding until every reader has answered; a lock
    // held over the decoding would keep them waiting and the hook gives up. Then the index is
    // the one of the whole file opened at once.
    void readersGoOnWhileAFollowDecodes() {
        std::string log;
        bench::generateLog(log, 20'000'000);
        const std::size_t cut = log.find('\n', 1'000'000) + 1;
        const std::string p = path("follow-big.nmea");
        QVERIFY(test::writeFile(p, std::string_view(log).substr(0, cut)));
        std::atomic<bool> inside{false}, readersDone{false}, readersSeen{false};
        LogViewOptions o;
        o.whileFollowing = [&] {
            inside = true;
            readersSeen = test::waitForFlag(readersDone);
        };
        LogView view(registry_, o);
        QVERIFY(test::openAndWait(view, p));
        const std::size_t before = view.epochCount();
        QVERIFY(before > 100);
        {
            std::FILE *f = std::fopen(p.c_str(), "ab");
            QVERIFY(f);
            QCOMPARE(std::fwrite(log.data() + cut, 1, log.size() - cut, f), log.size() - cut);
            QCOMPARE(std::fclose(f), 0);
        }
        LogView::FollowResult r;
        std::thread follower([&] { r = view.follow(); });
        const bool entered = test::waitForFlag(inside);
        // Every reader answers, from the index as it was, while the growth is decoded.
        const std::size_t during = view.epochCount();
        ReceiverState s;
        const bool state = view.stateAt(before - 1, s);
        const bool lines = !view.linesAround(view.indexedEnd(), 3, 1).empty();
        std::size_t seen = 0;
        view.withRecords([&](std::span<const EpochRecord> all) { seen = all.size(); });
        view.events();
        view.stats(0, before - 1);
        readersDone = true;
        follower.join();
        QVERIFY(entered);
        QVERIFY(readersSeen);
        QCOMPARE(during, before);
        QCOMPARE(seen, before);
        QVERIFY(state && lines);
        QVERIFY(r.grew);
        QVERIFY(r.firstChanged <= before);
        // The same index as the whole file's.
        LogView whole(registry_);
        QVERIFY(test::openAndWait(whole, p));
        QVERIFY(view.epochCount() > before * 10);
        test::compareIndexes(view, whole, 5);
    }

    // Offsets past 4 GB: a sparse file (5 GB of hole, no disk used) with a log at its end,
    // indexed from there.
    void offsetsPastFourGigabytes() {
        const std::string text = test::scenarioLog({});
        const std::string p = path("sparse.nmea");
        const std::uint64_t at = (std::uint64_t(5) << 30) + 123;
        const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        QVERIFY(fd >= 0);
        if (::pwrite(fd, text.data(), text.size(), static_cast<off_t>(at)) !=
            static_cast<ssize_t>(text.size())) {
            ::close(fd);
            QSKIP("this file system cannot hold a 5 GB sparse file");
        }
        ::close(fd);
        LogViewOptions o;
        o.startOffset = at;
        LogView view(registry_, o);
        QVERIFY(test::openAndWait(view, p));
        QCOMPARE(view.fileSize(), at + text.size());
        QCOMPARE(view.epochCount(), std::size_t(600));
        QCOMPARE(view.epoch(0)->offset, at);
        QVERIFY(view.epoch(599)->offset > at);
        const auto truth = test::frontToBack(text, registry_);
        ReceiverState s;
        QVERIFY(view.stateAt(599, s));
        QVERIFY(s == truth[599]);
        const auto lines = view.linesAround(at + 5000, 2, 2);
        QCOMPARE(lines.size(), std::size_t(4));
        QVERIFY(lines[0].offset > (std::uint64_t(4) << 30));
        const std::string_view b = view.bytes(lines[2].offset, lines[2].length);
        QVERIFY(b.starts_with("$GP"));
        std::string out;
        view.exportRange(ExportFormat::Nmea, 0, 599, [&](std::string_view x) {
            out += x;
            return true;
        });
        QCOMPARE(out, text);
        QCOMPARE(view.epochAtOffset(at + text.size() - 1).value_or(0), std::size_t(599));
    }

    void cancelStopsTheWorker() {
        std::string big;
        bench::generateLog(big, 30'000'000);
        const std::string p = path("big.nmea");
        QVERIFY(test::writeFile(p, big));
        LogView view(registry_);
        view.open(p);
        view.cancel();
        QVERIFY(view.waitUntilIndexed(60000));
        QVERIFY(view.progress().phase == LogView::Phase::Cancelled ||
                view.progress().phase == LogView::Phase::Ready);
        // Opened again, it goes to the end, and the first epoch came before.
        QVERIFY(test::openAndWait(view, p));
        QVERIFY(view.firstEpoch());
        QCOMPARE(view.firstEpoch()->offset, std::uint64_t(0));
    }
};

QTEST_APPLESS_MAIN(TstLogviewInputs)
#include "tst_logview_inputs.moc"
