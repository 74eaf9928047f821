// JSON strings: UTF-8 text passes as it is (a receiver's name, a setting's "5°", a Russian label,
// a path), and any byte that is not text — a control character, junk from a serial line, a
// broken or overlong sequence — is written as \u00XX; the result always parses.
#include "core/json_writer.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

class TstJsonWriter : public QObject {
    Q_OBJECT
private slots:
    void strings_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QByteArray>("written"); // between the quotes
        QTest::addColumn<QString>("parsed");
        QTest::newRow("ascii") << QByteArray("GPGGA") << QByteArray("GPGGA") << "GPGGA";
        QTest::newRow("escapes") << QByteArray("a\"b\\c\n\t") << QByteArray("a\\\"b\\\\c\\n\\t")
                                 << "a\"b\\c\n\t";
        QTest::newRow("control") << QByteArray("x\x01y", 3) << QByteArray("x\\u0001y")
                                 << QString("x\x01y");
        QTest::newRow("delete") << QByteArray("\x7f") << QByteArray("\\u007f")
                                << QString(QChar(0x7f));
        QTest::newRow("degree") << QByteArray("5\xc2\xb0") << QByteArray("5\xc2\xb0")
                                << QString::fromUtf8("5\xc2\xb0");
        QTest::newRow("russian") << QByteArray("\xd0\x9c\xd0\xb0\xd1\x81\xd0\xba\xd0\xb0")
                                 << QByteArray("\xd0\x9c\xd0\xb0\xd1\x81\xd0\xba\xd0\xb0")
                                 << QString::fromUtf8("\xd0\x9c\xd0\xb0\xd1\x81\xd0\xba\xd0\xb0");
        QTest::newRow("four bytes")
                << QByteArray("\xf0\x9f\x9b\xb0") << QByteArray("\xf0\x9f\x9b\xb0")
                << QString::fromUtf8("\xf0\x9f\x9b\xb0");
        QTest::newRow("stray byte")
                << QByteArray("a\xb0z") << QByteArray("a\\u00b0z") << QString::fromLatin1("a\xb0z");
        QTest::newRow("cut short")
                << QByteArray("\xd0") << QByteArray("\\u00d0") << QString::fromLatin1("\xd0");
        QTest::newRow("overlong") << QByteArray("\xc0\xaf") << QByteArray("\\u00c0\\u00af")
                                  << QString::fromLatin1("\xc0\xaf");
        QTest::newRow("surrogate")
                << QByteArray("\xed\xa0\x80") << QByteArray("\\u00ed\\u00a0\\u0080")
                << QString::fromLatin1("\xed\xa0\x80");
        QTest::newRow("past U+10FFFF")
                << QByteArray("\xf4\x90\x80\x80") << QByteArray("\\u00f4\\u0090\\u0080\\u0080")
                << QString::fromLatin1("\xf4\x90\x80\x80");
    }
    void strings() {
        QFETCH(QByteArray, bytes);
        QFETCH(QByteArray, written);
        QFETCH(QString, parsed);
        std::string out;
        gnss::appendJsonString(out, std::string_view(bytes.constData(), std::size_t(bytes.size())));
        QCOMPARE(QByteArray::fromStdString(out), '"' + written + '"');
        std::string doc;
        gnss::JsonWriter(doc)
                .beginObject()
                .field("s", std::string(bytes.toStdString()))
                .endObject();
        QJsonParseError error{};
        const QJsonObject o =
                QJsonDocument::fromJson(QByteArray::fromStdString(doc), &error).object();
        QCOMPARE(error.error, QJsonParseError::NoError);
        QCOMPARE(o.value("s").toString(), parsed);
    }
};

QTEST_GUILESS_MAIN(TstJsonWriter)
#include "tst_json_writer.moc"
