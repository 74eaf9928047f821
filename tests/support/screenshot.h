#pragma once
// Screenshots of the views, kept for a person to look at when GNSS_SCREENSHOT_DIR names a folder.
#include <QByteArray>
#include <QImage>
#include <QString>
#include <QTest>
#include <QWidget>

namespace gnss::test {

// Saves `image` as `fileName` in GNSS_SCREENSHOT_DIR when that is set; false only when a save
// that was asked for failed.
inline bool saveScreenshot(const QImage &image, const QString &fileName) {
    const QByteArray dir = qgetenv("GNSS_SCREENSHOT_DIR");
    return dir.isEmpty() || image.save(QString::fromLocal8Bit(dir) + "/" + fileName);
}

// Grabs `w` as it is painted now: an image, saved as `fileName` when screenshots are kept.
inline void checkScreenshot(QWidget &w, const QString &fileName) {
    const QImage img = w.grab().toImage();
    QVERIFY(!img.isNull());
    QVERIFY(saveScreenshot(img, fileName));
}

} // namespace gnss::test
