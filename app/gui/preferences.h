#pragma once
// The user's preferences: language, theme, display units, coordinate format, time zone and the
// baud rates "auto" tries. Stored with QSettings; the Preferences dialog edits them and the main
// window applies them to every view.
#include "models/value_format.h"

#include <QList>
#include <QString>

class QSettings;

namespace gnss::app {

struct Preferences {
    QString language = QStringLiteral("system"); // "system", "en", "ru"
    QString theme = QStringLiteral("system");    // "system", "light", "dark"
    ui::DisplayPrefs display;
    QList<int> detectionBauds; // the order baud "auto" tries; empty: the built-in order

    static Preferences load(const QSettings &settings);
    void save(QSettings &settings) const;
    bool operator==(const Preferences &) const = default;
};

// The languages offered: "system" and each one the application has a translation for.
QStringList availableLanguages();
// The locale to translate into for a language preference ("system": the system's).
QString localeNameFor(const QString &language);

// "115200, 9600, 38400" -> the rates; on error an empty list and why (names the bad entry).
// Every rate must be one a serial port can be set to (kStandardBauds), each given once.
QList<int> parseBaudList(const QString &text, QString *error);
QString baudListText(const QList<int> &rates);
// The built-in detection order, for the dialog's default.
QList<int> defaultDetectionBauds();

} // namespace gnss::app
