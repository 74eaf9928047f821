// gnss-icon-export OUTDIR NAME SIZE...: the application icon (ui/style/app_icon.cpp) as PNG files
// OUTDIR/<SIZE>x<SIZE>/apps/NAME.png, the hicolor theme's layout, for the package. Run at build
// time, so the PNGs are drawn by the code that draws the window icon: never committed, never
// out of step with it.
#include "style/app_icon.h"

#include <QDir>
#include <QGuiApplication>

#include <cstdio>
#include <cstdlib>

int main(int argc, char **argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: gnss-icon-export OUTDIR NAME SIZE...\n");
        return 2;
    }
    // Pixmaps need a QGuiApplication, and a build machine has no display.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    const QString outDir = QString::fromLocal8Bit(argv[1]);
    const QString name = QString::fromLocal8Bit(argv[2]);
    for (int i = 3; i < argc; ++i) {
        const int size = std::atoi(argv[i]);
        if (size <= 0) {
            std::fprintf(stderr, "gnss-icon-export: not a size: %s\n", argv[i]);
            return 2;
        }
        const QString dir = QStringLiteral("%1/%2x%2/apps").arg(outDir).arg(size);
        const QString file = QStringLiteral("%1/%2.png").arg(dir, name);
        if (!QDir().mkpath(dir) || !gnss::style::appIconPixmap(size).save(file, "PNG")) {
            std::fprintf(stderr, "gnss-icon-export: cannot write %s\n", qPrintable(file));
            return 1;
        }
    }
    return 0;
}
