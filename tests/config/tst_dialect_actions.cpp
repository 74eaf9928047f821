// Each dialect record's receiver actions (save, defaults, cold/warm/hot start): the sentence
// sent is the spec's own example where the spec prints one (GeoS-5 §4.2-4.5, checksums as
// docs/spec-notes.md corrects the typeset "$GPGSGG, ..."), and every action of every dialect is a
// well-formed sentence that its own dialect decodes.
#include "builtin/dialects.h"
#include "config/dialect_actions.h"
#include "decode_helper.h"

#include <QTest>

using namespace gnss;

class TstDialectActions : public QObject {
    Q_OBJECT
    DialectRegistry registry_ = makeBuiltinRegistry();

private slots:
    void theSpecsExamples_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<int>("action");
        QTest::addColumn<QString>("sentence");
        const auto row = [](const char *name, const char *d, ReceiverAction a, const char *s) {
            QTest::newRow(name) << d << int(a) << s;
        };
        row("GeoS-5 4.2 SAVEFL", "geostar", ReceiverAction::SaveToFlash, "$GPSGG,SAVEFL*63");
        row("GeoS-5 4.3 CSTART", "geostar", ReceiverAction::ColdStart, "$GPSGG,CSTART*6B");
        row("GeoS-5 4.4 WSTART", "geostar", ReceiverAction::WarmStart, "$GPSGG,WSTART*7F");
        row("GeoS-5 4.5 HSTART", "geostar", ReceiverAction::HotStart, "$GPSGG,HSTART*60");
    }
    void theSpecsExamples() {
        QFETCH(QString, dialect);
        QFETCH(int, action);
        QFETCH(QString, sentence);
        const Dialect *d = registry_.find(dialect.toStdString());
        QVERIFY(d);
        const ActionDef *a = findAction(*d, ReceiverAction(action));
        QVERIFY(a);
        QCOMPARE(QString::fromStdString(config::actionSentence(*a)), sentence);
    }

    void everyActionDecodesInItsDialect_data() {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("sentence");
        for (const Dialect *d : registry_.dialects())
            for (const ActionDef &a : d->actions)
                QTest::newRow(qPrintable(QString::fromLatin1(d->id.data(), d->id.size()) + " " +
                                         QString::fromLatin1(a.body.data(), a.body.size())))
                        << QString::fromLatin1(d->id.data(), d->id.size())
                        << QString::fromStdString(config::actionSentence(a));
    }
    void everyActionDecodesInItsDialect() {
        QFETCH(QString, dialect);
        QFETCH(QString, sentence);
        DecoderOptions o;
        o.dialect = dialect.toStdString();
        const test::Decoded r = test::decodeOne(sentence, o);
        QCOMPARE(r.checksum, QString("ok"));
        QVERIFY2(r.ok, qPrintable(sentence + ": " + r.error));
    }
};

QTEST_GUILESS_MAIN(TstDialectActions)
#include "tst_dialect_actions.moc"
