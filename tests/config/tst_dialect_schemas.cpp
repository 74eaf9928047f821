// Every built-in dialect's settings schema: each row names the SettingCommand that writes it or
// reads it back (the engine makes its plans and read-backs from those; every access, read-write,
// write-only or read-only, is one or the other), so that no dialect has a setting the settings
// form shows but nothing can send or query.
#include "builtin_registry.h"

#include <QStringList>
#include <QTest>

using namespace gnss;

class TstDialectSchemas : public QObject {
    Q_OBJECT
private slots:
    void everySettingNamesItsCommand() {
        QStringList missing; // "dialect key" of each row without a command
        int rows = 0;
        for (const Dialect *d : test::builtinRegistry().dialects())
            for (const SettingDef &def : d->settings) {
                ++rows;
                if (!def.command)
                    missing << QString::fromStdString(std::string(d->id) + " " +
                                                      std::string(def.key));
            }
        QVERIFY(rows > 0);
        QCOMPARE(missing, QStringList());
    }
};

QTEST_APPLESS_MAIN(TstDialectSchemas)
#include "tst_dialect_schemas.moc"
