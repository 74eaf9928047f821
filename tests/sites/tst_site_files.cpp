// The site list's files (protocol/sites/site_formats.h, site_store.h): JSON and CSV round trips
// with awkward text, CSV and JSON errors with their place, and the user's sites.json written
// atomically (a failed write leaves the old file).
#include "sites/site_store.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

#include <sys/resource.h>
#include <unistd.h>

using namespace gnss::sites;

namespace {

std::vector<Site> sampleSites() {
    Site a;
    a.name = "Крыша НИИ";
    a.latDeg = 55.751234567891;
    a.lonDeg = 37.618412345678;
    a.height = 166.6;
    a.antennaHeight = 1.512;
    a.accuracy = 0.02;
    a.date = "2024-03-15";
    a.method = "survey-in";
    a.note = "by the mast, \"north\" side,\nsecond line";
    Site b;
    b.name = "Base, old";
    b.latDeg = -33.5;
    b.lonDeg = -70.25;
    b.method = "known";
    return {a, b};
}

void compareSites(const std::vector<Site> &got, const std::vector<Site> &want) {
    QCOMPARE(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        QCOMPARE(got[i].name, want[i].name);
        QCOMPARE(got[i].latDeg, want[i].latDeg);
        QCOMPARE(got[i].lonDeg, want[i].lonDeg);
        QCOMPARE(got[i].height, want[i].height);
        QCOMPARE(got[i].antennaHeight, want[i].antennaHeight);
        QCOMPARE(got[i].accuracy, want[i].accuracy);
        QCOMPARE(got[i].date, want[i].date);
        QCOMPARE(got[i].method, want[i].method);
        QCOMPARE(got[i].note, want[i].note);
    }
}

QString joined(const SitesRead &r) {
    QStringList l;
    for (const auto &e : r.errors) l << QString::fromStdString(e);
    return l.join('\n');
}

} // namespace

class TstSiteFiles : public QObject {
    Q_OBJECT
private slots:
    void jsonRoundTrip() {
        const std::string text = sitesToJson(sampleSites());
        QVERIFY(text.starts_with("{\"format\":\"gnss-workbench-sites\",\"version\":1,\"sites\":["));
        const SitesRead r = SiteStore::parseJson(QByteArray::fromStdString(text));
        QVERIFY2(r.ok(), qPrintable(joined(r)));
        compareSites(r.sites, sampleSites());
    }

    void csvRoundTrip() {
        const std::string text = sitesToCsv(sampleSites());
        QVERIFY(text.starts_with(
                "name,lat,lon,height,antenna_height,accuracy,date,method,note\r\n"));
        QVERIFY(text.find("\"by the mast, \"\"north\"\" side,") != std::string::npos);
        QVERIFY(text.find("\"Base, old\"") != std::string::npos);
        const SitesRead r = sitesFromCsv(text);
        QVERIFY2(r.ok(), qPrintable(joined(r)));
        compareSites(r.sites, sampleSites());
    }

    void csvColumnsInAnyOrder() {
        const SitesRead r = sitesFromCsv("\xEF\xBB\xBFLon,NAME,lat\n37.5,Roof,55.25\n\n");
        QVERIFY2(r.ok(), qPrintable(joined(r)));
        QCOMPARE(r.sites.size(), std::size_t(1));
        QCOMPARE(r.sites[0].name, std::string("Roof"));
        QCOMPARE(r.sites[0].latDeg, 55.25);
        QCOMPARE(r.sites[0].lonDeg, 37.5);
        QVERIFY(!r.sites[0].height);
    }

    void csvErrors_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("no lat column") << "name,lon\nA,1\n"
                                       << "line 1: no 'lat' column";
        QTest::newRow("unknown column") << "name,lat,lon,colour\nA,1,2,red\n"
                                        << "line 1: column 4 'colour' is not one of";
        QTest::newRow("column twice") << "name,lat,lon,lat\nA,1,2,3\n"
                                      << "line 1: column 4 'lat' is given twice";
        QTest::newRow("decimal comma") << "name,lat,lon\nA,1,2\nB,\"55,5\",37\n"
                                       << "line 3: lat: '55,5' is not a number";
        QTest::newRow("cells") << "name,lat,lon\nA,1\n"
                               << "line 2: 2 cells where the header has 3";
        QTest::newRow("range") << "name,lat,lon\nA,1,2\n\nB,95,2\n"
                               << "line 4: lat: 95 is not a latitude";
        QTest::newRow("empty lon") << "name,lat,lon\nA,1,\n"
                                   << "line 2: lon is empty";
        QTest::newRow("line numbers after a quoted line end")
                << "name,lat,lon,note\nA,1,2,\"two\nlines\"\nB,x,2,\n"
                << "line 4: lat: 'x'";
        QTest::newRow("open quote") << "name,lat,lon\nA,1,2\n\"B,1,2\n"
                                    << "line 3: a quote is never closed";
        QTest::newRow("same name twice") << "name,lat,lon\nRoof,1,2\nROOF,3,4\n"
                                         << "line 3: the name 'ROOF' is already used by line 2";
        QTest::newRow("bad name") << "name,lat,lon\n,1,2\n"
                                  << "line 2: name: a site's name cannot be empty";
        QTest::newRow("empty file") << ""
                                    << "line 1: no header";
    }
    void csvErrors() {
        QFETCH(QString, text);
        QFETCH(QString, error);
        const SitesRead r = sitesFromCsv(text.toStdString());
        QVERIFY(!r.ok());
        QVERIFY(r.sites.empty());
        QVERIFY2(joined(r).contains(error), qPrintable(joined(r)));
    }

    void jsonErrors_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("error");
        QTest::newRow("not json") << QByteArray("{") << "not JSON";
        QTest::newRow("other format")
                << QByteArray("{\"format\":\"x\",\"version\":1,\"sites\":[]}") << "not a site list";
        QTest::newRow("newer")
                << QByteArray("{\"format\":\"gnss-workbench-sites\",\"version\":2,\"sites\":[]}")
                << "version 2 of the site list is newer";
        QTest::newRow("lat text") << QByteArray("{\"format\":\"gnss-workbench-sites\",\"version\":"
                                                "1,\"sites\":[{\"name\":\"A\",\"lat\":1,\"lon\":2},"
                                                "{\"name\":\"Roof\",\"lat\":\"55\",\"lon\":37}]}")
                                  << "site 2 (\"Roof\"): field \"lat\": not a number";
        QTest::newRow("no lon") << QByteArray("{\"format\":\"gnss-workbench-sites\",\"version\":1,"
                                              "\"sites\":[{\"name\":\"Roof\",\"lat\":55}]}")
                                << "site 1 (\"Roof\"): field \"lon\" is missing";
        QTest::newRow("no name") << QByteArray("{\"format\":\"gnss-workbench-sites\",\"version\":1,"
                                               "\"sites\":[{\"lat\":55,\"lon\":3}]}")
                                 << "site 1: field \"name\" is missing";
        QTest::newRow("range") << QByteArray(
                                          "{\"format\":\"gnss-workbench-sites\",\"version\":1,"
                                          "\"sites\":[{\"name\":\"Roof\",\"lat\":55,\"lon\":300}]}")
                               << "site 1 (\"Roof\"): lon: 300 is not a longitude";
        QTest::newRow("twice") << QByteArray("{\"format\":\"gnss-workbench-sites\",\"version\":1,"
                                             "\"sites\":[{\"name\":\"A\",\"lat\":1,\"lon\":2},{"
                                             "\"name\":\"a\",\"lat\":1,\"lon\":2}]}")
                               << "site 2 (\"a\"): the name 'a' is already used by site 1 (\"A\")";
    }
    void jsonErrors() {
        QFETCH(QByteArray, text);
        QFETCH(QString, error);
        const SitesRead r = SiteStore::parseJson(text);
        QVERIFY(!r.ok());
        QVERIFY(r.sites.empty());
        QVERIFY2(joined(r).contains(error), qPrintable(joined(r)));
    }

    void storeSavesAndLoads() {
        QTemporaryDir dir;
        const SiteStore store(dir.filePath("made/here"));
        SiteList list;
        QString error;
        QVERIFY(store.load(list, error)); // no file yet: an empty list
        QVERIFY(list.empty());
        for (const Site &s : sampleSites()) list.add(s);
        QVERIFY2(store.save(list, error), qPrintable(error));
        SiteList again;
        QVERIFY2(store.load(again, error), qPrintable(error));
        compareSites(again.sites(), list.sites());
    }

    void failedSaveKeepsTheOldFile_data() {
        QTest::addColumn<bool>("readOnlyFolder"); // else: a file size limit the new file passes
        QTest::newRow("read-only folder") << true;
        QTest::newRow("write fails midway") << false;
    }
    void failedSaveKeepsTheOldFile() {
        QFETCH(bool, readOnlyFolder);
        if (readOnlyFolder && geteuid() == 0) QSKIP("root writes to a read-only folder");
        QTemporaryDir dir;
        const SiteStore store(dir.path());
        SiteList list;
        list.add(sampleSites()[0]);
        QString error;
        QVERIFY(store.save(list, error));
        QFile f(store.filePath());
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray before = f.readAll();
        f.close();
        for (int i = 0; i < 100; ++i) {
            Site s = sampleSites()[1];
            s.name = "Site " + std::to_string(i);
            list.add(s);
        }
        bool saved = false;
        if (readOnlyFolder) {
            QVERIFY(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner));
            saved = store.save(list, error);
            QFile::setPermissions(dir.path(),
                                  QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        } else {
            // Files beyond 1 KiB cannot be written (EFBIG, the signal ignored), even by root.
            rlimit old{};
            getrlimit(RLIMIT_FSIZE, &old);
            rlimit small = old;
            small.rlim_cur = 1024;
            const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
            QCOMPARE(setrlimit(RLIMIT_FSIZE, &small), 0);
            saved = store.save(list, error);
            setrlimit(RLIMIT_FSIZE, &old);
            std::signal(SIGXFSZ, oldHandler);
        }
        QVERIFY(!saved);
        QVERIFY2(error.contains(store.filePath()), qPrintable(error));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), before);
        SiteList kept;
        QVERIFY(store.load(kept, error));
        QCOMPARE(kept.size(), std::size_t(1));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"sites.json"});
    }

    void malformedStoreIsAnError() {
        QTemporaryDir dir;
        const SiteStore store(dir.path());
        QFile f(store.filePath());
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("[1,2");
        f.close();
        SiteList list;
        QString error;
        QVERIFY(!store.load(list, error));
        QVERIFY2(error.contains("not JSON"), qPrintable(error));
    }

    void directoryOverride() {
        qputenv(SiteStore::kDirectoryVariable, "/tmp/somewhere");
        QCOMPARE(SiteStore::defaultDirectory(), QString("/tmp/somewhere"));
        qunsetenv(SiteStore::kDirectoryVariable);
        QVERIFY(SiteStore::defaultDirectory().endsWith("/GNSS Workbench/GNSS Workbench"));
    }
};

QTEST_GUILESS_MAIN(TstSiteFiles)
#include "tst_site_files.moc"
