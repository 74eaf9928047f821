// Source tables written by the caster read back by the client's parser: every STR field the
// parser knows round-trips, a field cannot break its record, and the table ends as it should.
#include "ntrip/source_table.h"
#include "ntrip/source_table_writer.h"

#include <QTest>

using namespace gnss::ntrip;

namespace {

StreamEntry baseEntry() {
    StreamEntry e;
    e.mountpoint = "BASE";
    e.identifier = "Moscow";
    e.format = "RTCM 3.3";
    e.formatDetails = "1005(10),1077(1),1087(1),1230(5)";
    e.carrier = 2;
    e.navSystem = "GPS+GLO";
    e.network = "LOCAL";
    e.country = "RUS";
    e.latitude = 55.75;
    e.longitude = 37.62;
    e.wantsGga = false;
    e.solution = 0;
    e.generator = "GNSS Workbench";
    e.compression = "none";
    e.authentication = "B";
    e.fee = false;
    e.bitrate = 9600;
    e.misc = "";
    return e;
}

// Every field the parser reads, compared (the table of fields is the parser's own).
bool sameEntry(const StreamEntry &a, const StreamEntry &b) {
    bool same = true;
    for (const auto &f : streamFields())
        std::visit([&](auto member) { same = same && a.*member == b.*member; }, f.member);
    return same;
}

} // namespace

Q_DECLARE_METATYPE(gnss::ntrip::StreamEntry)

class TstSourceTableWriter : public QObject {
    Q_OBJECT
private slots:
    void recordsRoundTrip_data() {
        QTest::addColumn<StreamEntry>("entry");
        QTest::newRow("a base station") << baseEntry();
        StreamEntry open = baseEntry();
        open.mountpoint = "OPEN";
        open.authentication = "N";
        open.wantsGga = true;
        open.fee = true;
        open.solution = 1;
        open.latitude = -33.87;
        open.longitude = -151.21;
        open.misc = "misc; with; semicolons";
        QTest::newRow("open, network, southern, misc with ';'") << open;
        StreamEntry sparse;
        sparse.mountpoint = "SPARSE";
        sparse.authentication = "N";
        QTest::newRow("numbers unset") << sparse;
    }
    void recordsRoundTrip() {
        QFETCH(StreamEntry, entry);
        const std::vector<StreamEntry> streams{entry, baseEntry()};
        const std::string text = writeSourceTable(streams);
        const SourceTable t = parseSourceTable(text);
        QVERIFY(t.complete);
        QCOMPARE(t.badLines, 0u);
        QCOMPARE(t.shortRecords, 0u);
        QCOMPARE(t.streams.size(), std::size_t(2));
        QVERIFY2(sameEntry(t.streams[0], entry), text.c_str());
        QVERIFY(sameEntry(t.streams[1], baseEntry()));
    }

    void aRecordIsWrittenAsCastersWriteIt() {
        QCOMPARE(QByteArray::fromStdString(streamRecord(baseEntry())),
                 QByteArray("STR;BASE;Moscow;RTCM 3.3;1005(10),1077(1),1087(1),1230(5);2;GPS+GLO;"
                            "LOCAL;RUS;55.75;37.62;0;0;GNSS Workbench;none;B;N;9600;\r\n"));
        QCOMPARE(writeSourceTable({}), std::string("ENDSOURCETABLE\r\n"));
    }

    void aFieldCannotBreakItsRecord() {
        StreamEntry e = baseEntry();
        e.identifier = "two;fields\r\nSTR;EVIL;x";
        const std::string text = writeSourceTable(std::vector<StreamEntry>{e});
        const SourceTable t = parseSourceTable(text);
        QCOMPARE(t.streams.size(), std::size_t(1));
        QCOMPARE(t.streams[0].identifier, std::string("two,fieldsSTR,EVIL,x"));
        QCOMPARE(t.streams[0].bitrate, std::optional<int>(9600));
    }
};

QTEST_APPLESS_MAIN(TstSourceTableWriter)
#include "tst_source_table_writer.moc"
