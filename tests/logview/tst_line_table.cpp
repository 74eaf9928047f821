// The log viewer's console as a virtual list over the mapped file (LineTable, LogView::line):
// line k and the line holding an offset agree with a plain split of the text, whatever the line
// ends, overlong lines and cuts of a growing file; the filter finds exactly the lines a plain
// search finds; a whole generated log is counted and read back through LogView.
#include "builtin/dialects.h"
#include "log_generator.h"
#include "logview/line_table.h"
#include "logview/log_view.h"
#include "logview_files.h"

#include <QTemporaryDir>
#include <QTest>

#include <random>

using namespace gnss;
using namespace gnss::logview;

Q_DECLARE_METATYPE(std::string)

namespace {

struct Expected {
    std::uint64_t offset;
    std::string text;
};

// The lines as the console should show them, by the rule written plainly: split at '\n', a CR
// before it dropped, a stretch longer than the framer's longest line cut into pieces of it.
std::vector<Expected> plainSplit(const std::string &data) {
    std::vector<Expected> out;
    std::uint64_t pos = 0;
    while (pos < data.size()) {
        const std::size_t nl = data.find('\n', pos);
        const std::uint64_t stop = nl == std::string::npos ? data.size() : nl;
        std::uint64_t at = pos;
        while (stop - at > Framer::kMaxLine) { // a piece of exactly kMaxLine, then the rest
            out.push_back({at, data.substr(at, Framer::kMaxLine)});
            at += Framer::kMaxLine;
        }
        std::string text = data.substr(at, stop - at);
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (stop - at == Framer::kMaxLine && nl != std::string::npos) {
            // a piece of exactly kMaxLine before its '\n': the '\n' starts an empty line
            out.push_back({at, text});
            out.push_back({stop, std::string()});
        } else {
            out.push_back({at, text});
        }
        pos = nl == std::string::npos ? data.size() : nl + 1;
    }
    return out;
}

void compareAll(const LineTable &table, const std::string &data) {
    const auto expected = plainSplit(data);
    QCOMPARE(table.lineCount(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const auto r = table.line(data, k);
        QVERIFY(r);
        QCOMPARE(r->offset, expected[k].offset);
        QCOMPARE(data.substr(r->offset, r->length), expected[k].text);
    }
    QVERIFY(!table.line(data, expected.size()));
    // Every offset maps to the line holding it.
    std::size_t k = 0;
    for (std::uint64_t off = 0; off < data.size(); ++off) {
        while (k + 1 < expected.size() && expected[k + 1].offset <= off) ++k;
        if (table.lineAt(data, off) != k) {
            QFAIL(qPrintable(QStringLiteral("offset %1: line %2, expected %3")
                                     .arg(off)
                                     .arg(table.lineAt(data, off))
                                     .arg(k)));
        }
    }
}

std::string manyLines(std::size_t n) {
    std::string s;
    std::mt19937 rng(7);
    for (std::size_t i = 0; i < n; ++i) {
        s += "$GPGGA,";
        s += std::to_string(i);
        s += std::string(rng() % 40, 'x');
        s += rng() % 3 ? "\r\n" : "\n";
    }
    return s;
}

} // namespace

class TstLineTable : public QObject {
    Q_OBJECT
private slots:
    void linesAgreeWithAPlainSplit_data() {
        QTest::addColumn<std::string>("data");
        QTest::newRow("empty") << std::string();
        QTest::newRow("one line, no end") << std::string("$GPGGA,1*00");
        QTest::newRow("LF") << std::string("$A,1\n$B,2\n");
        QTest::newRow("CR LF") << std::string("$A,1\r\n$B,2\r\n");
        QTest::newRow("lone CR inside") << std::string("$A\r,1\n$B\r\r\n\r");
        QTest::newRow("empty lines") << std::string("\n\n\r\n\n$A\n\n");
        QTest::newRow("NUL bytes") << std::string("$A,\0,1\n\0\0\n$B", 13);
        QTest::newRow("10000 bytes of junk") << std::string(10000, '\x81');
        QTest::newRow("junk then a line") << std::string(9000, 'z') + "\n$GPGLL,1\n";
        QTest::newRow("line of exactly 4096") << std::string(4096, 'q') + "\n$A\n";
        QTest::newRow("line of 4095 + CR") << std::string(4095, 'q') + "\r\n$A\n";
        QTest::newRow("8192 then end") << std::string(8192, 'q');
        QTest::newRow("1000 lines (blocks of 256)") << manyLines(1000);
        QTest::newRow("exactly 512 lines") << manyLines(512);
    }
    void linesAgreeWithAPlainSplit() {
        QFETCH(std::string, data);
        LineTable table;
        QVERIFY(table.extend(data));
        compareAll(table, data);
    }

    // A file being written: counted as it grows, cut anywhere (between CR and LF, inside an
    // overlong line), it gives the table of the whole.
    void aGrowingFileGivesTheWholeTable() {
        const std::string data = manyLines(700) + std::string(5000, 'j') + "\r\n$END,1";
        std::mt19937 rng(11);
        for (int round = 0; round < 20; ++round) {
            LineTable table;
            std::uint64_t at = 0;
            while (at < data.size()) {
                at = std::min<std::uint64_t>(data.size(), at + 1 + rng() % 3000);
                QVERIFY(table.extend(std::string_view(data).substr(0, at)));
                QCOMPARE(table.scanned(), at);
            }
            compareAll(table, data);
        }
    }

    void aShorterFileIsCountedAgain() {
        const std::string data = manyLines(600);
        LineTable table;
        QVERIFY(table.extend(data));
        const std::string cut = data.substr(0, data.size() / 3);
        QVERIFY(table.extend(cut));
        compareAll(table, cut);
    }

    void aCancelledCountKeepsTheOneBefore() {
        const std::string data = manyLines(200'000);
        LineTable table;
        QVERIFY(table.extend(std::string_view(data).substr(0, 1000)));
        const auto before = table.lineCount();
        std::atomic<bool> cancel{true};
        QVERIFY(!table.extend(data, &cancel));
        QCOMPARE(table.lineCount(), before);
        QVERIFY(table.extend(data));
        QCOMPARE(table.lineCount(), std::uint64_t(200'000));
    }

    void addressesAreWhatASentenceSays_data() {
        QTest::addColumn<std::string>("line");
        QTest::addColumn<std::string>("address");
        QTest::newRow("GGA") << std::string("$GPGGA,1,2*33") << std::string("GPGGA");
        QTest::newRow("AIS") << std::string("!AIVDM,1") << std::string("AIVDM");
        QTest::newRow("no fields") << std::string("$PNVGVER*5A") << std::string("PNVGVER");
        QTest::newRow("blank before comma") << std::string("$GPGSV ,1") << std::string("GPGSV");
        QTest::newRow("not a sentence") << std::string("hello,world") << std::string();
        QTest::newRow("empty") << std::string() << std::string();
    }
    void addressesAreWhatASentenceSays() {
        QFETCH(std::string, line);
        QFETCH(std::string, address);
        QCOMPARE(std::string(LineTable::addressOf(line)), address);
    }

    // The filter finds the lines a plain search finds, stops at its limit, and goes on over what
    // a growing file gained.
    void theFilterFindsWhatAPlainSearchFinds() {
        std::string data;
        for (int i = 0; i < 3000; ++i)
            data += i % 7 == 0 ? "$GNRMC,x\r\n" : i % 5 == 0 ? "junk\n" : "$GPGGA,y\n";
        const auto lines = plainSplit(data);
        std::vector<std::uint64_t> want;
        for (const auto &l : lines)
            if (l.text.rfind("$GNRMC", 0) == 0) want.push_back(l.offset);
        auto keep = [](std::string_view a) { return a.find("RMC") != std::string_view::npos; };

        LineTable table;
        QVERIFY(table.extend(data));
        LineTable::Matches all;
        QVERIFY(table.findLines(data, keep, 1'000'000, all));
        QCOMPARE(all.offsets, want);
        QVERIFY(!all.full);

        LineTable::Matches some;
        QVERIFY(table.findLines(data, keep, 10, some));
        QCOMPARE(some.offsets.size(), std::size_t(10));
        QVERIFY(some.full);
        QCOMPARE(some.offsets, std::vector<std::uint64_t>(want.begin(), want.begin() + 10));

        LineTable growing;
        LineTable::Matches found;
        for (std::size_t at = 0; at < data.size(); at += 777) {
            QVERIFY(growing.extend(std::string_view(data).substr(0, at)));
            QVERIFY(growing.findLines(std::string_view(data).substr(0, at), keep, 1'000'000,
                                      found));
        }
        QVERIFY(growing.extend(data));
        QVERIFY(growing.findLines(data, keep, 1'000'000, found));
        QCOMPARE(found.offsets, want);
    }

    // Through LogView, on a generated 10 Hz log: every line read back is the file's line, the
    // line where each epoch ends holds that offset, and the lines agree with linesAround().
    void aWholeLogReadsBackThroughLogView() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("drive.nmea").toStdString();
        std::string text;
        bench::generateLog(text, 3'000'000);
        QVERIFY(test::writeFile(path, text));
        const DialectRegistry registry = makeBuiltinRegistry();
        LogView view(registry);
        QVERIFY(test::openAndWait(view, path));
        QCOMPARE(view.lineCount(), std::uint64_t(0)); // not counted until asked
        const auto expected = plainSplit(text);
        QCOMPARE(view.indexLines(), expected.size());
        QCOMPARE(view.lineCount(), expected.size());
        for (std::size_t k = 0; k < expected.size(); k += 97) {
            const auto r = view.line(k);
            QVERIFY(r);
            QCOMPARE(r->offset, expected[k].offset);
            QCOMPARE(std::string(view.bytes(r->offset, r->length)), expected[k].text);
        }
        for (std::size_t e = 0; e < view.epochCount(); e += 13) {
            const std::uint64_t end = view.epochEnd(e);
            const auto k = view.lineAt(end > 0 ? end - 1 : 0);
            const auto r = view.line(k);
            QVERIFY(r);
            QVERIFY(r->offset < end);
            const auto around = view.linesAround(end - 1, 0, 1);
            QCOMPARE(around.size(), std::size_t(1));
            QCOMPARE(around[0].offset, r->offset);
            QCOMPARE(around[0].length, r->length);
        }
    }
};

QTEST_APPLESS_MAIN(TstLineTable)
#include "tst_line_table.moc"
