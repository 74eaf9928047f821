// The times users type for --at, --from, --to and the timeline's "Go to" box (parseTimeSpec):
// every accepted form gives its exact milliseconds, and anything else is refused, so that the
// caller can say so before seeking.
#include "logview/log_time.h"

#include <QTest>

using namespace gnss::logview;

class TstLogTime : public QObject {
    Q_OBJECT
private slots:
    void accepted_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("kind");
        QTest::addColumn<qint64>("value"); // ms (UTC or of the day), or the epoch number
        const auto utc = int(TimeSpec::Kind::Utc), day = int(TimeSpec::Kind::TimeOfDay),
                   epoch = int(TimeSpec::Kind::Epoch);
        const qint64 march15 = 1710460800000; // 2024-03-15T00:00:00Z
        QTest::newRow("hh:mm:ss") << "10:42:00" << day << qint64(38'520'000);
        QTest::newRow("hh:mm") << "10:42" << day << qint64(38'520'000);
        QTest::newRow("h:mm:ss") << "9:42:05" << day << qint64(34'925'000);
        QTest::newRow("h:mm") << "0:00" << day << qint64(0);
        QTest::newRow("fraction") << "10:42:00.25" << day << qint64(38'520'250);
        QTest::newRow("Z") << "23:59:59Z" << day << qint64(86'399'000);
        QTest::newRow("leap second") << "23:59:60" << day << qint64(86'400'000);
        QTest::newRow("ISO") << "2024-03-15T10:42:00Z" << utc << march15 + 38'520'000;
        QTest::newRow("date and blank") << "2024-03-15 10:42:00.5" << utc << march15 + 38'520'500;
        QTest::newRow("one-digit hour after a date")
                << "2024-03-15T9:42" << utc << march15 + 34'920'000;
        QTest::newRow("date only") << "2024-03-15" << utc << march15;
        QTest::newRow("epoch") << "#1200" << epoch << qint64(1200);
        QTest::newRow("epoch 0") << "#0" << epoch << qint64(0);
    }
    void accepted() {
        QFETCH(QString, text);
        QFETCH(int, kind);
        QFETCH(qint64, value);
        const auto t = parseTimeSpec(text.toStdString());
        QVERIFY(t);
        QCOMPARE(int(t->kind), kind);
        QCOMPARE(t->kind == TimeSpec::Kind::Epoch ? qint64(t->epoch) : qint64(t->ms), value);
    }

    void refused_data() {
        QTest::addColumn<QString>("text");
        for (const char *s : {"", "yesterday", "24:00", "10:60", "10:42:61", "1042", ":42", "10:4",
                              "123:00", "10:42:00x", "#", "#-1", "#12a", "2024-13-01", "2024-03-32",
                              "2024-03-15X10:00", "2024-03-15T25:00"})
            QTest::newRow(*s ? s : "(empty)") << QString::fromLatin1(s);
    }
    void refused() {
        QFETCH(QString, text);
        QVERIFY(!parseTimeSpec(text.toStdString()));
    }
};

QTEST_APPLESS_MAIN(TstLogTime)
#include "tst_log_time.moc"
