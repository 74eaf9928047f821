// HiDPI: the binary under a real X server (Xvfb) at QT_SCALE_FACTOR=2 on a 2560x1600 screen, as
// a 4K laptop runs it, against the same at scale 1 on 1280x800.
//
// What is checked, and why it is robust:
//  - The window fills the 2560x1600 screen (grabbed from the X server with gnss-screengrab): at
//    scale 2 its 1280x800 logical pixels cover the whole screen, while an application that
//    ignored the factor would paint only the top-left quarter.
//  - The window's own picture (--screenshot) says DevicePixelRatio 2 and is 2560x1600.
//  - The views are painted at device resolution, not painted at 1x and enlarged. The measure is
//    the number of 2x2 device-pixel blocks, aligned on logical pixels, that hold a sharp step
//    (their darkest and lightest pixel differ by at least kStep levels): detail finer than one
//    logical pixel, which only painting at 2x produces (antialiased circle edges, text). A view
//    painted at 1x and enlarged has none: nearest-neighbour enlarging makes every block uniform,
//    and smooth enlarging spreads each step over two device pixels, so a block holds at most
//    about half of it. The test shows the measure tells them apart on this very screen: the
//    scale-1 picture of the same view, enlarged both ways, must score far below the scale-2
//    one. Satellites move between the two runs, so the comparison is by a wide margin, not by
//    pixels.
#include <QColor>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace {

constexpr int kStep = 96; // levels of luma (0..255) that make a step "sharp"

int luma(QRgb c) {
    return (qRed(c) * 299 + qGreen(c) * 587 + qBlue(c) * 114) / 1000;
}

// 2x2 blocks (aligned on even device pixels) within `r` whose pixels span >= kStep in luma.
int sharpBlocks(const QImage &img, const QRect &r) {
    int n = 0;
    for (int y = r.top() & ~1; y + 1 <= r.bottom(); y += 2)
        for (int x = r.left() & ~1; x + 1 <= r.right(); x += 2) {
            const int a = luma(img.pixel(x, y)), b = luma(img.pixel(x + 1, y)),
                      c = luma(img.pixel(x, y + 1)), d = luma(img.pixel(x + 1, y + 1));
            if (std::max({a, b, c, d}) - std::min({a, b, c, d}) >= kStep) ++n;
        }
    return n;
}

// "x,y,w,h" from the screenshot's text chunk for a dock (logical pixels).
QRect viewRect(const QImage &shot, const QString &dock) {
    const QStringList v = shot.text(QStringLiteral("View ") + dock).split(',');
    if (v.size() != 4) return {};
    return QRect(v[0].toInt(), v[1].toInt(), v[2].toInt(), v[3].toInt());
}

QRect scaled(const QRect &r, int f) {
    return QRect(r.x() * f, r.y() * f, r.width() * f, r.height() * f);
}

struct Run {
    QImage screen; // the X server's screen
    QImage shot;   // the window's own picture (--screenshot)
    QString log;
};

// Runs gnss-workbench on the simulated NV08C-RTK under Xvfb at `scale` on a `screen`-sized
// display; grabs the screen after 6 s, the window saves its picture at 9 s and quits.
Run runAt(double scale, QSize screen, const QTemporaryDir &dir, const QString &tag) {
    Run run;
    const QString shot = dir.filePath(tag + "-window.png");
    const QString grab = dir.filePath(tag + "-screen.png");
    // The grabber runs at scale 1 whatever the application does: it saves the screen's pixels.
    const QString script =
            QStringLiteral("\"%1\" --sim nvs --screenshot \"%2\" --quit-after 9 & app=$!; "
                           "sleep 6; QT_SCALE_FACTOR=1 \"%3\" \"%4\"; grabbed=$?; wait $app; "
                           "app_rc=$?; echo \"grab=$grabbed app=$app_rc\"; exit $app_rc")
                    .arg(GNSS_WORKBENCH_PATH, shot, GNSS_SCREENGRAB_PATH, grab);
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("QT_QPA_PLATFORM"); // the real X server, not offscreen
    for (const char *v : {"QT_SCREEN_SCALE_FACTORS", "QT_AUTO_SCREEN_SCALE_FACTOR",
                          "QT_ENABLE_HIGHDPI_SCALING", "QT_FONT_DPI"})
        env.remove(v);
    env.insert("QT_SCALE_FACTOR", QString::number(scale));
    env.insert("XDG_CONFIG_HOME", dir.filePath(tag + "-config")); // a first start each time
    env.insert("HOME", dir.path());
    p.setProcessEnvironment(env);
    p.start(QStandardPaths::findExecutable("xvfb-run"),
            {"-a", "-s",
             QStringLiteral("-screen 0 %1x%2x24").arg(screen.width()).arg(screen.height()), "sh",
             "-c", script});
    if (!p.waitForStarted(5000) || !p.waitForFinished(90000)) {
        p.kill();
        run.log = QStringLiteral("did not finish");
        return run;
    }
    run.log = QString::fromLocal8Bit(p.readAllStandardOutput() + p.readAllStandardError());
    if (p.exitCode() != 0 || !run.log.contains("grab=0")) return run;
    run.screen.load(grab);
    run.shot.load(shot); // QImage keeps the PNG's text chunks
    return run;
}

} // namespace

class TstGuiHidpi : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    Run one_, two_;

private slots:
    void initTestCase() {
        if (QStandardPaths::findExecutable("xvfb-run").isEmpty())
            QSKIP("xvfb-run is not installed (Debian package xvfb)");
        one_ = runAt(1, {1280, 800}, dir_, "scale1");
        QVERIFY2(!one_.shot.isNull() && !one_.screen.isNull(), qPrintable(one_.log));
        two_ = runAt(2, {2560, 1600}, dir_, "scale2");
        QVERIFY2(!two_.shot.isNull() && !two_.screen.isNull(), qPrintable(two_.log));
        if (qEnvironmentVariableIsSet("GNSS_HIDPI_KEEP")) { // to look at them
            one_.shot.save(qEnvironmentVariable("GNSS_HIDPI_KEEP") + "/scale1.png");
            two_.shot.save(qEnvironmentVariable("GNSS_HIDPI_KEEP") + "/scale2.png");
        }
    }

    void theWindowIsPaintedAtTwiceTheResolution() {
        QCOMPARE(one_.shot.text("DevicePixelRatio"), QString("1"));
        QCOMPARE(two_.shot.text("DevicePixelRatio"), QString("2"));
        // The same logical window, twice the pixels each way.
        QCOMPARE(two_.shot.size(), one_.shot.size() * 2);
        QCOMPARE(two_.shot.size(), QSize(2560, 1600));
        QCOMPARE(viewRect(two_.shot, "skyDock"), viewRect(one_.shot, "skyDock"));
    }

    void theWindowFillsTheScreen() {
        QCOMPARE(two_.screen.size(), QSize(2560, 1600));
        // The bottom-right quarter holds the window too (Xvfb's empty root is black).
        const QRect quarter(1280, 800, 1280, 800);
        int black = 0, samples = 0;
        for (int y = quarter.top(); y <= quarter.bottom(); y += 8)
            for (int x = quarter.left(); x <= quarter.right(); x += 8, ++samples)
                if (luma(two_.screen.pixel(x, y)) < 8) ++black;
        QVERIFY2(black < samples / 4,
                 qPrintable(QStringLiteral("%1 of %2 samples black").arg(black).arg(samples)));
    }

    void theViewsHoldDetailFinerThanALogicalPixel_data() {
        QTest::addColumn<QString>("dock");
        QTest::newRow("sky plot") << "skyDock";
        QTest::newRow("signal levels") << "signalDock";
        QTest::newRow("fix") << "fixDock";
        QTest::newRow("console") << "consoleDock";
    }
    void theViewsHoldDetailFinerThanALogicalPixel() {
        QFETCH(QString, dock);
        const QRect logical = viewRect(two_.shot, dock);
        QVERIFY2(logical.isValid(), qPrintable(dock + " not in the screenshot"));
        const int atTwo = sharpBlocks(two_.shot, scaled(logical, 2));
        // The scale-1 picture of the same view, enlarged as a 1x painting would be.
        const QImage one = one_.shot.copy(viewRect(one_.shot, dock));
        const QImage nearest =
                one.scaled(one.size() * 2, Qt::IgnoreAspectRatio, Qt::FastTransformation);
        const QImage smooth =
                one.scaled(one.size() * 2, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
        const int enlargedNearest = sharpBlocks(nearest, nearest.rect());
        const int enlargedSmooth = sharpBlocks(smooth, smooth.rect());
        qInfo("%s: %d sharp 2x2 blocks at scale 2; the scale-1 view enlarged: %d (nearest), %d "
              "(smooth)",
              qPrintable(dock), atTwo, enlargedNearest, enlargedSmooth);
        QCOMPARE(enlargedNearest, 0); // the measure sees no detail in a 1x picture enlarged
        QVERIFY2(atTwo >= 100, qPrintable(QString::number(atTwo)));
        QVERIFY2(atTwo >= 5 * std::max(1, enlargedSmooth),
                 qPrintable(QStringLiteral("%1 vs %2").arg(atTwo).arg(enlargedSmooth)));
    }
};

QTEST_GUILESS_MAIN(TstGuiHidpi)
#include "tst_gui_hidpi.moc"
