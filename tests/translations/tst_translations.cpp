// The translations are finished: every message of every translations/*.ts has a translation
// (none "unfinished", none empty), keeps the source's placeholders (%1, %n ...), has the three
// plural forms Russian needs where the source counts, and keeps one keyboard accelerator where
// the source has one. Refresh the .ts with the update_translations target, then translate.
#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QTest>
#include <QXmlStreamReader>

namespace {

struct Message {
    QString context, source, translation;
    QStringList numerusForms;
    bool numerus = false, unfinished = false;
    qint64 line = 0;
};

QList<Message> readTs(const QString &path, QString &error) {
    QList<Message> out;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        error = f.errorString();
        return out;
    }
    QXmlStreamReader x(&f);
    QString context;
    Message m;
    while (!x.atEnd()) {
        x.readNext();
        if (!x.isStartElement()) continue;
        const auto name = x.name();
        if (name == QLatin1String("name")) {
            context = x.readElementText();
        } else if (name == QLatin1String("message")) {
            m = Message{};
            m.context = context;
            m.numerus = x.attributes().value("numerus") == QLatin1String("yes");
            m.line = x.lineNumber();
        } else if (name == QLatin1String("source")) {
            m.source = x.readElementText();
        } else if (name == QLatin1String("translation")) {
            const auto type = x.attributes().value("type");
            m.unfinished = type == QLatin1String("unfinished");
            if (type == QLatin1String("vanished") || type == QLatin1String("obsolete")) continue;
            if (m.numerus) {
                while (x.readNextStartElement()) m.numerusForms << x.readElementText();
            } else {
                m.translation = x.readElementText();
            }
            out << m;
        }
    }
    if (x.hasError()) error = x.errorString();
    return out;
}

QSet<QString> placeholders(const QString &s) {
    static const QRegularExpression re(QStringLiteral("%(L?\\d+|n)"));
    QSet<QString> set;
    for (auto it = re.globalMatch(s); it.hasNext();) set << it.next().captured(0);
    return set;
}

// A '&' that marks an accelerator: not "&&", and followed by a letter or digit.
bool hasAccelerator(const QString &s) {
    for (qsizetype i = 0; i + 1 < s.size(); ++i) {
        if (s[i] != QLatin1Char('&')) continue;
        if (s[i + 1] == QLatin1Char('&')) {
            ++i;
            continue;
        }
        if (s[i + 1].isLetterOrNumber()) return true;
    }
    return false;
}

} // namespace

class TstTranslations : public QObject {
    Q_OBJECT
private slots:
    void everyStringIsTranslated_data() {
        QTest::addColumn<QString>("path");
        const QDir dir(QStringLiteral(GNSS_TRANSLATIONS_DIR));
        const QStringList files = dir.entryList({"*.ts"}, QDir::Files);
        QVERIFY2(!files.isEmpty(), "no .ts file");
        for (const QString &f : files) QTest::newRow(qPrintable(f)) << dir.filePath(f);
    }
    void everyStringIsTranslated() {
        QFETCH(QString, path);
        QString error;
        const QList<Message> messages = readTs(path, error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(messages.size() > 100);
        QStringList problems;
        auto say = [&](const Message &m, const QString &what) {
            problems << QStringLiteral("line %1 [%2] \"%3\": %4")
                                .arg(m.line)
                                .arg(m.context, m.source.left(60), what);
        };
        for (const Message &m : messages) {
            if (m.unfinished) {
                say(m, QStringLiteral("unfinished"));
                continue;
            }
            const QStringList forms = m.numerus ? m.numerusForms : QStringList{m.translation};
            if (m.numerus && forms.size() != 3) say(m, QStringLiteral("needs three plural forms"));
            for (const QString &t : forms) {
                if (t.trimmed().isEmpty() && !m.source.trimmed().isEmpty())
                    say(m, QStringLiteral("empty"));
                else if (placeholders(t) != placeholders(m.source))
                    say(m, QStringLiteral("placeholders differ: \"%1\"").arg(t));
                else if (hasAccelerator(m.source) && !hasAccelerator(t))
                    say(m, QStringLiteral("lost its keyboard accelerator: \"%1\"").arg(t));
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("%1 of %2 messages:\n")
                                                        .arg(problems.size())
                                                        .arg(messages.size()) +
                                                problems.join('\n')));
    }
};

QTEST_GUILESS_MAIN(TstTranslations)
#include "tst_translations.moc"
