// gnss-workbench: the GUI entry point.
#include "main_window.h"
#include "startup_options.h"
#include "style/app_icon.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>
#include <QPixmap>
#include <QTimer>
#include <cstdio>

int main(int argc, char **argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName("GNSS Workbench");
    QApplication::setOrganizationName("GNSS Workbench");
    QApplication::setApplicationVersion(QStringLiteral("0.1.0"));

    // The interface in the user's language where we have it (translations/), Qt's own strings too.
    QTranslator qtTranslator, appTranslator;
    if (qtTranslator.load(QLocale(), "qtbase", "_", QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);
    if (appTranslator.load(QLocale(), "gnss-workbench", "_", ":/i18n"))
        QApplication::installTranslator(&appTranslator);

    QString error;
    const auto options = gnss::app::parseStartupOptions(QApplication::arguments(), error);
    if (!options) {
        std::fprintf(stderr, "gnss-workbench: %s\n", qPrintable(error));
        return 2;
    }

    QApplication::setWindowIcon(gnss::style::appIcon());
    gnss::app::MainWindow window;
    window.show();

    const double delay = options->quitAfter > 0 ? options->quitAfter : (options->screenshot.isEmpty() ? 0 : 1);
    if (delay > 0) {
        QTimer::singleShot(static_cast<int>(delay * 1000), &app, [&] {
            if (!options->screenshot.isEmpty()) {
                const QPixmap shot = window.grab();
                if (!shot.save(options->screenshot)) {
                    std::fprintf(stderr, "gnss-workbench: cannot save %s\n",
                                 qPrintable(options->screenshot));
                    QApplication::exit(1);
                    return;
                }
            }
            QApplication::quit();
        });
    }
    return QApplication::exec();
}
