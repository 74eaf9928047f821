// gnss-workbench: the GUI entry point.
#include "app_transports.h"
#include "dialects.h"
#include "main_window.h"
#include "startup_options.h"
#include "style/app_icon.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QPixmap>
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

    // The interface in the user's language where we have it (translations/), Qt's own strings too.
    QTranslator qtTranslator, appTranslator;
    if (qtTranslator.load(QLocale(), "qtbase", "_",
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);
    if (appTranslator.load(QLocale(), "gnss-workbench", "_", ":/i18n"))
        QApplication::installTranslator(&appTranslator);

    QString error;
    const auto options = gnss::app::parseStartupOptions(QApplication::arguments(),
                                                        gnss::app::simulatedDialects(), error);
    if (!options) {
        std::fprintf(stderr, "gnss-workbench: %s\n", qPrintable(error));
        return 2;
    }

    QApplication::setWindowIcon(gnss::style::appIcon());
    const gnss::DialectRegistry registry = gnss::makeBuiltinRegistry();
    const gnss::link::TransportFactory transports = gnss::app::makeTransportFactory();
    QSettings settings;
    gnss::app::MainWindow window(registry, transports, &settings);
    window.show();
    using gnss::app::SourceSpec;
    SourceSpec start;
    if (!options->port.isEmpty())
        start = {SourceSpec::Kind::Serial, options->port, options->baud};
    else if (!options->tcp.isEmpty())
        start = {SourceSpec::Kind::Tcp, options->tcp};
    else if (!options->replay.isEmpty())
        start = {SourceSpec::Kind::Replay, options->replay};
    else if (!options->sim.isEmpty())
        start = {SourceSpec::Kind::Simulator, options->sim};
    window.connectAtStart(start);

    const double delay =
            options->quitAfter > 0 ? options->quitAfter : (options->screenshot.isEmpty() ? 0 : 1);
    if (delay > 0) {
        QTimer::singleShot(static_cast<int>(delay * 1000), &app, [&] {
            if (!options->screenshot.isEmpty()) {
                window.saveLayout();
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
