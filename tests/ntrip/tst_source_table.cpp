// Source tables: every STR field read, CAS and NET records, the table RTKLIB's caster sends,
// short and garbage lines counted, and the same table whatever the chunking.
#include "ntrip/source_table.h"
#include "source_table_examples.h"

#include <QTest>

using namespace gnss::ntrip;
using namespace ntrip_test;

class TstSourceTable : public QObject {
    Q_OBJECT
private slots:
    void everyStreamFieldIsRead() {
        const SourceTable t = parseSourceTable(kSourceTable);
        QVERIFY(t.complete);
        QCOMPARE(int(t.streams.size()), 3);
        const StreamEntry &s = t.streams[0];
        QCOMPARE(s.mountpoint, std::string("MOSC00RUS0"));
        QCOMPARE(s.identifier, std::string("Moscow"));
        QCOMPARE(s.format, std::string("RTCM 3.2"));
        QCOMPARE(s.formatDetails, std::string("1005(10),1074(1),1084(1),1230(10)"));
        QCOMPARE(s.carrier.value_or(-1), 2);
        QCOMPARE(s.navSystem, std::string("GPS+GLO"));
        QCOMPARE(s.network, std::string("IGS"));
        QCOMPARE(s.country, std::string("RUS"));
        QCOMPARE(s.latitude.value_or(0), 55.75);
        QCOMPARE(s.longitude.value_or(0), 37.62);
        QVERIFY(!s.wantsGga);
        QCOMPARE(s.solution.value_or(-1), 0);
        QCOMPARE(s.generator, std::string("NV08C-RTK"));
        QCOMPARE(s.compression, std::string("none"));
        QCOMPARE(s.authentication, std::string("B"));
        QVERIFY(!s.fee);
        QCOMPARE(s.bitrate.value_or(0), 9600);
        QCOMPARE(s.misc, std::string("misc;with;semicolons"));
        const StreamEntry *vrs = t.find("VRS_RTCM3");
        QVERIFY(vrs);
        QVERIFY(vrs->wantsGga);
        QVERIFY(vrs->fee);
        QCOMPARE(vrs->solution.value_or(-1), 1);
        QCOMPARE(t.shortRecords, 0u);
        QCOMPARE(t.badLines, 0u);
    }

    void casterAndNetworkRecordsAreRead() {
        const SourceTable t = parseSourceTable(kSourceTable);
        QCOMPARE(int(t.casters.size()), 1);
        QCOMPARE(t.casters[0].host, std::string("caster.example.org"));
        QCOMPARE(t.casters[0].port.value_or(0), 2101);
        QCOMPARE(t.casters[0].fallbackHost, std::string("fallback.example.org"));
        QCOMPARE(t.casters[0].fallbackPort.value_or(0), 2102);
        QCOMPARE(t.casters[0].misc, std::string("http://example.org"));
        QCOMPARE(int(t.networks.size()), 1);
        QCOMPARE(t.networks[0].identifier, std::string("NET1"));
        QCOMPARE(t.networks[0].webReg, std::string("http://reg"));
        QCOMPARE(t.networks[0].misc, std::string("none"));
    }

    void rtklibCastersTableIsRead() {
        const SourceTable t = parseSourceTable(kRtklibSourceTable);
        QVERIFY(t.complete);
        QCOMPARE(int(t.streams.size()), 1);
        QCOMPARE(t.streams[0].mountpoint, std::string("MOUNT"));
        QCOMPARE(t.streams[0].bitrate.value_or(0), 9600);
        QCOMPARE(t.shortRecords, 0u);
    }

    void shortAndGarbageLinesAreCounted_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<int>("streams");
        QTest::addColumn<int>("shortRecords");
        QTest::addColumn<int>("badLines");
        QTest::addColumn<int>("longLines");
        QTest::newRow("a short STR keeps what it has")
                << QByteArray("STR;M1;Place;RTCM 3\r\n") << 1 << 1 << 0 << 0;
        QTest::newRow("an STR without a mountpoint is bad")
                << QByteArray("STR;;x;RTCM 3\r\n") << 0 << 0 << 1 << 0;
        QTest::newRow("garbage and HTML are bad")
                << QByteArray("<html>\r\nhello\r\nSTR;M;x\r\n\xff\xfe\r\n") << 1 << 1 << 3 << 0;
        QTest::newRow("blank lines are nothing")
                << QByteArray("\r\n\r\n  \r\n") << 0 << 0 << 0 << 0;
        QTest::newRow("a line over 4096 bytes is dropped")
                << ("STR;" + QByteArray(5000, 'a') + "\r\nSTR;OK;x\r\n") << 1 << 1 << 0 << 1;
        QTest::newRow("fields that are not numbers stay unset")
                << QByteArray("STR;M;x;RTCM 3;;two;GPS;N;RUS;north;east;x;y;g;none;B;N;fast;\r\n")
                << 1 << 0 << 0 << 0;
        QTest::newRow("bare LF line ends")
                << QByteArray("STR;A;x\nSTR;B;y\nENDSOURCETABLE\n") << 2 << 2 << 0 << 0;
    }
    void shortAndGarbageLinesAreCounted() {
        QFETCH(QByteArray, text);
        QFETCH(int, streams);
        QFETCH(int, shortRecords);
        QFETCH(int, badLines);
        QFETCH(int, longLines);
        const SourceTable t = parseSourceTable(text.toStdString());
        QCOMPARE(int(t.streams.size()), streams);
        QCOMPARE(int(t.shortRecords), shortRecords);
        QCOMPARE(int(t.badLines), badLines);
        QCOMPARE(int(t.longLines), longLines);
        for (const StreamEntry &s : t.streams) {
            QVERIFY(!s.carrier || *s.carrier >= 0);
            QVERIFY(!s.latitude || (*s.latitude >= -90 && *s.latitude <= 90));
        }
    }

    void theTableDoesNotDependOnChunking() {
        const std::string text = kSourceTable;
        const SourceTable whole = parseSourceTable(text);
        for (std::size_t cut = 1; cut < text.size(); ++cut) {
            SourceTableParser p;
            p.feed(std::string_view(text).substr(0, cut));
            p.feed(std::string_view(text).substr(cut));
            p.finish();
            const SourceTable &t = p.table();
            QCOMPARE(t.streams.size(), whole.streams.size());
            QCOMPARE(t.streams[2].bitrate, whole.streams[2].bitrate);
            QCOMPARE(t.streams[0].misc, whole.streams[0].misc);
            QCOMPARE(t.casters[0].misc, whole.casters[0].misc);
            QCOMPARE(t.complete, true);
        }
    }

    void aLastLineWithoutLineEndIsRead() {
        SourceTableParser p;
        p.feed("STR;A;x;RTCM 3\r\nENDSOURCETABLE");
        QVERIFY(!p.complete());
        p.finish();
        QVERIFY(p.complete());
    }

    void rtcm3FormatsAreRecognised_data() {
        QTest::addColumn<QString>("format");
        QTest::addColumn<bool>("rtcm3");
        QTest::newRow("RTCM 3") << "RTCM 3" << true;
        QTest::newRow("RTCM 3.2") << "RTCM 3.2" << true;
        QTest::newRow("RTCM3.3") << "RTCM3.3" << true;
        QTest::newRow("rtcm 3.1 lower case") << "rtcm 3.1" << true;
        QTest::newRow("RTCM_3") << "RTCM_3" << true;
        QTest::newRow("RTCM 2.3") << "RTCM 2.3" << false;
        QTest::newRow("CMR+") << "CMR+" << false;
        QTest::newRow("RAW") << "RAW" << false;
        QTest::newRow("empty") << "" << false;
    }
    void rtcm3FormatsAreRecognised() {
        QFETCH(QString, format);
        QFETCH(bool, rtcm3);
        QCOMPARE(isRtcm3Format(format.toStdString()), rtcm3);
    }
};

QTEST_APPLESS_MAIN(TstSourceTable)
#include "tst_source_table.moc"
