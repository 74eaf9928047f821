// gnss-workbench: the GUI entry point.
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "common/app_transports.h"
#include "gui/main_window.h"
#include "gui/preferences.h"
#include "gui/startup_options.h"
#include "gui/window_screenshot.h"
#include "gui/window_start.h"
#include "style/app_icon.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTimer>
#include <QTranslator>
#include <cstdio>

int main(int argc, char **argv) {
    // --help and --version print and quit: they must work without a display (over ssh, in a
    // package's test), so no window system is asked for then.
    if (gnss::app::asksForHelpOrVersion(argc, argv) &&
        qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QApplication::setApplicationName("GNSS Workbench");
    QApplication::setOrganizationName("GNSS Workbench");
    QApplication::setApplicationVersion(QStringLiteral(GNSS_VERSION));
    // The installed desktop entry (packaging/): Wayland compositors match windows to it by this.
    QApplication::setDesktopFileName(QStringLiteral(GNSS_APP_ID));

    // The interface in the language of the preferences (the system's by default) where we have
    // it (translations/), Qt's own strings too. English is the source language: no translator.
    QSettings settings;
    const QString language = gnss::app::Preferences::load(settings).language;
    const QLocale locale(gnss::app::localeNameFor(language));
    QTranslator qtTranslator, appTranslator;
    if (language != QLatin1String("en")) {
        if (qtTranslator.load(locale, "qtbase", "_",
                              QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
            QApplication::installTranslator(&qtTranslator);
        if (appTranslator.load(locale, "gnss-workbench", "_", ":/i18n"))
            QApplication::installTranslator(&appTranslator);
    }

    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    QString error;
    const auto options = gnss::app::parseStartupOptions(
            QApplication::arguments(), gnss::app::simulatedDialects(gnss::sim::builtinSimulators()),
            error);
    if (!options) {
        std::fprintf(stderr, "gnss-workbench: %s\n", qPrintable(error));
        return 2;
    }
    if (const QString missing = gnss::app::missingLog(*options); !missing.isEmpty()) {
        std::fprintf(stderr, "gnss-workbench: %s\n", qPrintable(missing));
        return 1;
    }

    QApplication::setWindowIcon(gnss::style::appIcon());
    const gnss::link::TransportFactory transports =
            gnss::app::makeTransportFactory(gnss::sim::builtinSimulators());
    gnss::app::MainWindow window(registry, transports, &settings);
    window.show();
    const QString startError = gnss::app::startWindow(window, *options);
    if (!startError.isEmpty()) {
        std::fprintf(stderr, "gnss-workbench: %s\n", qPrintable(startError));
        return 2;
    }

    const double delay =
            options->quitAfter > 0 ? options->quitAfter : (options->screenshot.isEmpty() ? 0 : 1);
    if (delay > 0) {
        QTimer::singleShot(static_cast<int>(delay * 1000), &app, [&] {
            if (!options->screenshot.isEmpty()) {
                window.saveLayout();
                QString why;
                if (!gnss::app::saveWindowScreenshot(window, options->screenshot, &why)) {
                    std::fprintf(stderr, "gnss-workbench: cannot save %s: %s\n",
                                 qPrintable(options->screenshot), qPrintable(why));
                    QApplication::exit(1);
                    return;
                }
            }
            QApplication::quit();
        });
    }
    return QApplication::exec();
}
