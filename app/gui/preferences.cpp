#include "gui/preferences.h"

#include "core/baud_rates.h"

#include <QCoreApplication>
#include <QLocale>
#include <QRegularExpression>
#include <QSettings>

namespace gnss::app {

Preferences Preferences::load(const QSettings &s) {
    Preferences p;
    const QString language = s.value("ui/language", p.language).toString();
    if (availableLanguages().contains(language)) p.language = language;
    const QString theme = s.value("view/theme", p.theme).toString();
    if (theme == QLatin1String("light") || theme == QLatin1String("dark")) p.theme = theme;
    p.display.units = ui::unitSystemFromKey(s.value("view/units").toString());
    p.display.coordinates = ui::coordinateFormatFromKey(s.value("view/coordinates").toString());
    p.display.time = ui::timeZoneFromKey(s.value("view/time").toString());
    QString ignored;
    p.detectionBauds = parseBaudList(s.value("link/detectionBauds").toString(), &ignored);
    return p;
}

void Preferences::save(QSettings &s) const {
    s.setValue("ui/language", language);
    s.setValue("view/theme", theme);
    s.setValue("view/units", ui::toKey(display.units));
    s.setValue("view/coordinates", ui::toKey(display.coordinates));
    s.setValue("view/time", ui::toKey(display.time));
    if (detectionBauds.isEmpty() || detectionBauds == defaultDetectionBauds())
        s.remove("link/detectionBauds");
    else
        s.setValue("link/detectionBauds", baudListText(detectionBauds));
}

QStringList availableLanguages() {
    return {QStringLiteral("system"), QStringLiteral("en"), QStringLiteral("ru")};
}

QString localeNameFor(const QString &language) {
    return language == QLatin1String("system") ? QLocale().name() : language;
}

QList<int> parseBaudList(const QString &text, QString *error) {
    QList<int> out;
    const QStringList parts =
            text.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
    for (const QString &part : parts) {
        bool ok = false;
        const int rate = part.toInt(&ok);
        if (!ok || !isStandardBaud(rate)) {
            if (error)
                *error = QCoreApplication::translate("Preferences",
                                                     "'%1' is not a serial port speed")
                                 .arg(part);
            return {};
        }
        if (out.contains(rate)) {
            if (error)
                *error = QCoreApplication::translate("Preferences", "%1 is listed twice").arg(rate);
            return {};
        }
        out << rate;
    }
    if (out.isEmpty() && error)
        *error = QCoreApplication::translate("Preferences", "List at least one speed");
    return out;
}

QString baudListText(const QList<int> &rates) {
    QStringList parts;
    for (int r : rates) parts << QString::number(r);
    return parts.join(QStringLiteral(", "));
}

QList<int> defaultDetectionBauds() {
    return QList<int>(kDetectionBauds.begin(), kDetectionBauds.end());
}

} // namespace gnss::app
