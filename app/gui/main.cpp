// gnss-workbench: the GUI entry point.
#include "main_window.h"
#include "startup_options.h"

#include <QApplication>
#include <QPixmap>
#include <QTimer>
#include <cstdio>

int main(int argc, char **argv) {
    QApplication app(argc, argv);
    QApplication::setApplicationName("GNSS Workbench");
    QApplication::setOrganizationName("GNSS Workbench");
    QApplication::setApplicationVersion(QStringLiteral("0.1.0"));

    QString error;
    const auto options = gnss::app::parseStartupOptions(QApplication::arguments(), error);
    if (!options) {
        std::fprintf(stderr, "gnss-workbench: %s\n", qPrintable(error));
        return 2;
    }

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
