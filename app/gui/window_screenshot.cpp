#include "gui/window_screenshot.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QHash>
#include <QImage>
#include <QImageWriter>
#include <QMainWindow>
#include <QPixmap>

#include <algorithm>
#include <vector>

namespace gnss::app {

namespace {

// The window in at most 256 colours: the 256 commonest, every other pixel mapped to the nearest
// of them. A window is mostly flat colours, and the rarer shades are the edges of antialiased
// text and curves, which the nearest common shade draws the same to the eye; the PNG becomes a
// third of its size (pictures for a README, a bug report).
QImage withPalette(const QImage &image) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    QHash<QRgb, qsizetype> counts;
    for (int y = 0; y < rgb.height(); ++y) {
        const auto *line = reinterpret_cast<const QRgb *>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x) ++counts[line[x]];
    }
    std::vector<std::pair<qsizetype, QRgb>> byCount;
    byCount.reserve(counts.size());
    for (auto it = counts.cbegin(); it != counts.cend(); ++it)
        byCount.push_back({it.value(), it.key()});
    const std::size_t keep = std::min<std::size_t>(256, byCount.size());
    std::partial_sort(byCount.begin(), byCount.begin() + keep, byCount.end(),
                      [](const auto &a, const auto &b) { return a.first > b.first; });
    QList<QRgb> table;
    for (std::size_t i = 0; i < keep; ++i) table << byCount[i].second;
    QImage out = rgb.convertToFormat(QImage::Format_Indexed8, table, Qt::ThresholdDither);
    for (const QString &key : image.textKeys()) out.setText(key, image.text(key));
    return out;
}

} // namespace

bool saveWindowScreenshot(QMainWindow &window, const QString &path, QString *error) {
    const QPixmap shot = window.grab();
    QImage image = shot.toImage();
    image.setText(QStringLiteral("Software"),
                  QStringLiteral("%1 %2").arg(QCoreApplication::applicationName(),
                                              QCoreApplication::applicationVersion()));
    image.setText(QStringLiteral("DevicePixelRatio"), QString::number(shot.devicePixelRatio()));
    for (const QDockWidget *d : window.findChildren<QDockWidget *>()) {
        const QWidget *w = d->widget();
        if (!w || !w->isVisible() || d->isFloating()) continue;
        const QRect r(w->mapTo(&window, QPoint(0, 0)), w->size());
        image.setText(
                QStringLiteral("View ") + d->objectName(),
                QStringLiteral("%1,%2,%3,%4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height()));
    }
    QImageWriter writer(path, "png");
    writer.setQuality(0); // for PNG the strongest compression
    if (writer.write(withPalette(image))) return true;
    if (error) *error = writer.errorString();
    return false;
}

} // namespace gnss::app
