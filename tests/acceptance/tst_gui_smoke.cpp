// The binary as a user starts it, on a real X server (Xvfb at 1280x800): started on the
// simulated NV08C-RTK, a screenshot of the screen after a few seconds shows a window that is
// not blank, and the program exits cleanly by itself (--quit-after).
#include <QColor>
#include <QHash>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

class TstGuiSmoke : public QObject {
    Q_OBJECT
private slots:
    void theWorkbenchStartsDrawsAndQuitsUnderXvfb() {
        const QString xvfbRun = QStandardPaths::findExecutable("xvfb-run");
        if (xvfbRun.isEmpty()) QSKIP("xvfb-run is not installed (Debian package xvfb)");
        QTemporaryDir dir;
        const QString shot = dir.filePath("screen.png");
        const QString script = QStringLiteral("\"%1\" --sim nvs --quit-after 9 & app=$!; sleep 6; "
                                              "\"%2\" \"%3\"; grabbed=$?; wait $app; app_rc=$?; "
                                              "echo \"grab=$grabbed app=$app_rc\"; exit $app_rc")
                                       .arg(GNSS_WORKBENCH_PATH, GNSS_SCREENGRAB_PATH, shot);
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("QT_QPA_PLATFORM");                         // the real X server, not offscreen
        env.insert("XDG_CONFIG_HOME", dir.filePath("config")); // a first start
        env.insert("HOME", dir.path());
        p.setProcessEnvironment(env);
        p.start(xvfbRun, {"-a", "-s", "-screen 0 1280x800x24", "sh", "-c", script});
        QVERIFY(p.waitForStarted(5000));
        QVERIFY2(p.waitForFinished(60000), "did not quit by itself");
        const QByteArray out = p.readAllStandardOutput() + p.readAllStandardError();
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QVERIFY2(p.exitCode() == 0, out.constData());
        QVERIFY2(out.contains("grab=0"), out.constData());

        QImage img(shot);
        QVERIFY2(!img.isNull(), "no screenshot");
        QCOMPARE(img.size(), QSize(1280, 800));
        // Not blank: many colours, and no single colour covering almost everything.
        QHash<QRgb, int> colours;
        for (int y = 0; y < img.height(); y += 2)
            for (int x = 0; x < img.width(); x += 2) ++colours[img.pixel(x, y)];
        int most = 0;
        for (int n : colours) most = std::max(most, n);
        const int samples = (img.width() / 2) * (img.height() / 2);
        qInfo("screenshot: %d colours, the commonest on %.0f %%", int(colours.size()),
              100.0 * most / samples);
        QVERIFY2(colours.size() > 40, qPrintable(QString::number(colours.size())));
        QVERIFY(most < samples * 0.9);
        // The constellation colours of the sky plot and signal bars are on screen (GPS blue,
        // GLONASS vermillion): the views drew data, not only empty frames.
        QVERIFY(colours.contains(QColor(0x00, 0x72, 0xB2).rgb()));
        QVERIFY(colours.contains(QColor(0xD5, 0x5E, 0x00).rgb()));
    }
};

QTEST_GUILESS_MAIN(TstGuiSmoke)
#include "tst_gui_smoke.moc"
