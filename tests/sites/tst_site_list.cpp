// The site list (protocol/sites/site.h): name rules, look-up by name and unique prefix, adding,
// replacing and merging, and a site's antenna reference point.
#include "sites/site.h"

#include <QTest>

using namespace gnss::sites;

namespace {

Site siteNamed(const std::string &name, double lat = 55.75, double lon = 37.61) {
    Site s;
    s.name = name;
    s.latDeg = lat;
    s.lonDeg = lon;
    return s;
}

SiteList listOf(std::initializer_list<const char *> names) {
    SiteList l;
    for (const char *n : names) l.add(siteNamed(n));
    return l;
}

} // namespace

class TstSiteList : public QObject {
    Q_OBJECT
private slots:
    void nameRules_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("problem"); // part of the words; empty: a good name
        QTest::newRow("plain") << "Roof"
                               << "";
        QTest::newRow("cyrillic") << "Крыша НИИ"
                                  << "";
        QTest::newRow("64 characters") << QString(64, QChar(0x436)) << "";
        QTest::newRow("empty") << ""
                               << "empty";
        QTest::newRow("65 characters") << QString(65, 'a') << "at most 64";
        QTest::newRow("tab") << "a\tb"
                             << "control";
        QTest::newRow("newline") << "a\nb"
                                 << "control";
        QTest::newRow("delete") << "a\x7f"
                                << "control";
        QTest::newRow("leading space") << " Roof"
                                       << "space";
        QTest::newRow("trailing space") << "Roof "
                                        << "space";
    }
    void nameRules() {
        QFETCH(QString, name);
        QFETCH(QString, problem);
        const QString why = QString::fromStdString(nameProblem(name.toStdString()));
        if (problem.isEmpty())
            QVERIFY2(why.isEmpty(), qPrintable(why));
        else
            QVERIFY2(why.contains(problem), qPrintable(why));
    }

    void notUtf8() { QVERIFY(!nameProblem("a\xff").empty()); }

    void siteChecks_data() {
        QTest::addColumn<double>("lat");
        QTest::addColumn<double>("lon");
        QTest::addColumn<double>("height");
        QTest::addColumn<double>("accuracy");
        QTest::addColumn<QString>("date");
        QTest::addColumn<QString>("field"); // empty: a good site
        QTest::newRow("good") << 55.0 << 37.0 << 150.0 << 0.02 << "2024-03-15"
                              << "";
        QTest::newRow("date and time") << 55.0 << 37.0 << 150.0 << 0.02 << "2024-03-15T10:00:00Z"
                                       << "";
        QTest::newRow("lat 91") << 91.0 << 37.0 << 150.0 << 0.02 << ""
                                << "lat:";
        QTest::newRow("lon -181") << 55.0 << -181.0 << 150.0 << 0.02 << ""
                                  << "lon:";
        QTest::newRow("height 1e6") << 55.0 << 37.0 << 1e6 << 0.02 << ""
                                    << "height:";
        QTest::newRow("accuracy < 0") << 55.0 << 37.0 << 1.0 << -1.0 << ""
                                      << "accuracy:";
        QTest::newRow("date 15.03.2024") << 55.0 << 37.0 << 1.0 << 1.0 << "15.03.2024"
                                         << "date:";
        QTest::newRow("month 13") << 55.0 << 37.0 << 1.0 << 1.0 << "2024-13-01"
                                  << "date:";
    }
    void siteChecks() {
        QFETCH(double, lat);
        QFETCH(double, lon);
        QFETCH(double, height);
        QFETCH(double, accuracy);
        QFETCH(QString, date);
        QFETCH(QString, field);
        Site s = siteNamed("A", lat, lon);
        s.height = height;
        s.accuracy = accuracy;
        s.date = date.toStdString();
        const QString why = QString::fromStdString(siteProblem(s));
        if (field.isEmpty())
            QVERIFY2(why.isEmpty(), qPrintable(why));
        else
            QVERIFY2(why.startsWith(field), qPrintable(why));
    }

    void namesCompareWithoutCase_data() {
        QTest::addColumn<QString>("a");
        QTest::addColumn<QString>("b");
        QTest::addColumn<bool>("same");
        QTest::newRow("ascii") << "ROOF"
                               << "roof" << true;
        QTest::newRow("cyrillic") << "КРЫША НИИ"
                                  << "крыша нии" << true;
        QTest::newRow("yo") << "Ёлка"
                            << "ёлка" << true;
        QTest::newRow("latin-1") << "ÉCOLE"
                                 << "école" << true;
        QTest::newRow("different") << "Roof A"
                                   << "Roof B" << false;
    }
    void namesCompareWithoutCase() {
        QFETCH(QString, a);
        QFETCH(QString, b);
        QFETCH(bool, same);
        QCOMPARE(sameName(a.toStdString(), b.toStdString()), same);
    }

    void addReplaceRemove() {
        SiteList l;
        QCOMPARE(l.add(siteNamed("Roof")), SiteList::AddResult::Added);
        QCOMPARE(l.add(siteNamed("ROOF", 1, 2)), SiteList::AddResult::Conflict);
        QCOMPARE(l.find("roof")->latDeg, 55.75);
        QCOMPARE(l.add(siteNamed("ROOF", 1, 2), true), SiteList::AddResult::Replaced);
        QCOMPARE(l.size(), std::size_t(1));
        QCOMPARE(l.find("Roof")->name, std::string("ROOF"));
        QCOMPARE(l.add(siteNamed("Bad", 95, 0)), SiteList::AddResult::Invalid);
        QVERIFY(l.remove("roof"));
        QVERIFY(!l.remove("roof"));
        QVERIFY(l.empty());
    }

    void sortedListing() {
        const SiteList l = listOf({"b", "C", "a", "Крыша"});
        std::vector<std::string> names;
        for (const Site &s : l.sites()) names.push_back(s.name);
        QCOMPARE(names, (std::vector<std::string>{"a", "b", "C", "Крыша"}));
    }

    void lookup_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("found"); // empty: none
        QTest::addColumn<bool>("ambiguous");
        QTest::addColumn<QStringList>("candidates");
        QTest::newRow("exact") << "Roof"
                               << "Roof" << false << QStringList();
        QTest::newRow("exact beats prefix") << "roof"
                                            << "Roof" << false << QStringList();
        QTest::newRow("unique prefix") << "base"
                                       << "Base 1" << false << QStringList();
        QTest::newRow("cyrillic prefix") << "крыш"
                                         << "Крыша НИИ" << false << QStringList();
        QTest::newRow("ambiguous") << "ro"
                                   << "" << true << QStringList{"Roof", "Roof B"};
        QTest::newRow("typo") << "Rooof"
                              << "" << false << QStringList{"Roof", "Roof B"};
        QTest::newRow("unknown") << "Zzzzzzzz"
                                 << "" << false << QStringList();
    }
    void lookup() {
        QFETCH(QString, text);
        QFETCH(QString, found);
        QFETCH(bool, ambiguous);
        QFETCH(QStringList, candidates);
        const SiteList l = listOf({"Roof", "Roof B", "Base 1", "Крыша НИИ"});
        const SiteList::Lookup r = l.lookup(text.toStdString());
        QCOMPARE(r.site ? QString::fromStdString(r.site->name) : QString(), found);
        QCOMPARE(r.ambiguous, ambiguous);
        QStringList got;
        for (const auto &c : r.candidates) got << QString::fromStdString(c);
        QCOMPARE(got, candidates);
    }

    void mergeReportsConflicts_data() {
        QTest::addColumn<bool>("replace");
        QTest::newRow("kept") << false;
        QTest::newRow("replaced") << true;
    }
    void mergeReportsConflicts() {
        QFETCH(bool, replace);
        SiteList l = listOf({"Roof", "Mast"});
        const auto r = l.merge({siteNamed("roof", 10, 20), siteNamed("New")}, replace);
        QCOMPARE(r.added, std::vector<std::string>{"New"});
        QCOMPARE(r.replaced.size(), std::size_t(replace ? 1 : 0));
        QCOMPARE(r.conflicts.size(), std::size_t(replace ? 0 : 1));
        QCOMPARE(l.size(), std::size_t(3));
        QCOMPARE(l.find("Roof")->latDeg, replace ? 10.0 : 55.75);
    }

    void antennaReferencePoint_data() {
        QTest::addColumn<bool>("hasHeight");
        QTest::addColumn<double>("expected");
        QTest::newRow("with height") << true << 151.5;
        QTest::newRow("no height") << false << 1.5;
    }
    void antennaReferencePoint() {
        QFETCH(bool, hasHeight);
        QFETCH(double, expected);
        Site s = siteNamed("A");
        if (hasHeight) s.height = 150.0;
        s.antennaHeight = 1.5;
        const gnss::wgs84::Geodetic arp = s.antennaReferencePoint();
        QCOMPARE(arp.height, expected);
        const auto back = gnss::wgs84::toGeodetic(s.antennaReferenceEcef());
        QVERIFY(back);
        QVERIFY(std::abs(back->height - expected) < 1e-3);
        QVERIFY(std::abs(back->latDeg - 55.75) < 1e-9);
    }

    void surveyIn() {
        const Site s = surveyInSite("Base", {55.0, 37.0, 180.0}, 0.05, "2024-03-15");
        QCOMPARE(s.method, std::string("survey-in"));
        QCOMPARE(s.antennaHeight, 0.0);
        QCOMPARE(*s.height, 180.0);
        QVERIFY(siteProblem(s).empty());
    }
};

QTEST_GUILESS_MAIN(TstSiteList)
#include "tst_site_list.moc"
