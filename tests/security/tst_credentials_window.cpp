// The corrections path in the real MainWindow never shows or keeps a caster's credentials: the
// simulated receiver connected and recorded, the dock filled in with a distinctive password and
// started against the test caster (accepted, refused, a caster echoing them back, credentials
// typed into the host field); then no text in the window (the dock's status, the status bar,
// the console's lines and its command history, every label), no Qt message (qDebug, qWarning:
// what would reach standard error), no file of the session (the settings file, the recording
// and its index) holds the password, "user:password" or their Base64. The password stays in
// the password field and, when asked and the build has one, the system keychain.
#include "gui/corrections_controller.h"
#include "laptop_window.h"
#include "models/receiver_state_model.h"
#include "rtcm_fixtures.h"
#include "secret_scan.h"
#include "session/receiver_link.h"
#include "test_caster.h"

#include <QAbstractItemModel>
#include <QAbstractItemView>
#include <QCheckBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMutex>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>
#include <QTimer>

using namespace gnss;
using gnss::app::SourceSpec;
using gnss::session::ReceiverLink;
using gnss::test::kSecretPassword;
using gnss::test::kSecretUser;
using gnss::test::SecretForms;

namespace {

// Every Qt message of the test (what gnss-workbench would print on standard error).
QMutex messagesLock;
QStringList messages;
QtMessageHandler previousHandler = nullptr;

void keepMessage(QtMsgType type, const QMessageLogContext &context, const QString &text) {
    {
        QMutexLocker lock(&messagesLock);
        messages << text;
    }
    if (previousHandler) previousHandler(type, context, text);
}

// Every text the window shows: labels, line edits (but the password's own field), plain text,
// the status bar, the window title and the rows of every item view (the console's lines).
QStringList shownTexts(QWidget *window) {
    QStringList out{window->windowTitle()};
    for (auto *l : window->findChildren<QLabel *>()) out << l->text() << l->toolTip();
    for (auto *e : window->findChildren<QLineEdit *>())
        if (e->objectName() != QLatin1String("correctionsPassword")) out << e->text();
    for (auto *t : window->findChildren<QPlainTextEdit *>()) out << t->toPlainText();
    for (auto *s : window->findChildren<QStatusBar *>()) out << s->currentMessage();
    for (auto *v : window->findChildren<QAbstractItemView *>()) {
        const QAbstractItemModel *m = v->model();
        if (!m) continue;
        for (int r = 0; r < m->rowCount(); ++r)
            for (int c = 0; c < m->columnCount(); ++c)
                out << m->data(m->index(r, c)).toString()
                    << m->data(m->index(r, c), Qt::ToolTipRole).toString();
    }
    return out;
}

QByteArray echoingReply() {
    const SecretForms s;
    return "HTTP/1.1 403 Forbidden for " + s.forms[1] + " (Basic " + s.forms[2] +
           ")\r\nContent-Length: 0\r\n\r\n";
}

} // namespace

class TstCredentialsWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { previousHandler = qInstallMessageHandler(keepMessage); }
    void cleanupTestCase() { qInstallMessageHandler(previousHandler); }

    void theWindowNeverShowsOrKeepsThem_data() {
        QTest::addColumn<QByteArray>("typedPassword");
        QTest::addColumn<QByteArray>("rawReply");
        QTest::addColumn<bool>("inHost"); // "user:password@127.0.0.1" typed as the host
        QTest::addColumn<bool>("remember");
        QTest::addColumn<QString>("status"); // in the dock's status line
        for (const bool remember : {false, true}) {
            const QByteArray tag = remember ? ", remember asked" : "";
            QTest::newRow("accepted" + tag)
                    << kSecretPassword << QByteArray() << false << remember << "Receiving RTCM";
            QTest::newRow("refused" + tag) << QByteArray("Wrong-9q8w7e-pass") << QByteArray()
                                           << false << remember << "refused the user name";
        }
        QTest::newRow("a caster that echoes them") << kSecretPassword << echoingReply() << false
                                                   << false << "Forbidden for *** (Basic ***)";
        QTest::newRow("typed into the host field")
                << kSecretPassword << QByteArray() << true << false << "Give only the host";
    }
    void theWindowNeverShowsOrKeepsThem() {
        QFETCH(QByteArray, typedPassword);
        QFETCH(QByteArray, rawReply);
        QFETCH(bool, inHost);
        QFETCH(bool, remember);
        QFETCH(QString, status);
        {
            QMutexLocker lock(&messagesLock);
            messages.clear();
        }
        corrections_test::TstCaster caster;
        caster.user = kSecretUser;
        caster.password = kSecretPassword;
        caster.rawReply = rawReply;
        QVERIFY(caster.listen());
        const QList<QByteArray> epochs = corrections_test::baseEpochs(30);
        int next = 0;
        QTimer pump;
        connect(&pump, &QTimer::timeout, [&] {
            if (caster.streamingClients() > 0 && next < epochs.size()) caster.send(epochs[next++]);
        });
        pump.start(200);

        gnss::test::LaptopWindow window;
        app::MainWindow &w = window.w;
        // A receiver (the built-in simulator), recorded: the corrections go into it.
        w.connectAtStart(SourceSpec{SourceSpec::Kind::Simulator, QStringLiteral("nvs")});
        QTRY_COMPARE_WITH_TIMEOUT(w.link()->state(), ReceiverLink::State::Connected, 20000);
        const QString recording = window.dir.filePath("receiver.nmea");
        QVERIFY(w.link()->startRecording(recording));
        const auto epochsBefore = w.stateModel()->epochCount();
        QTRY_VERIFY_WITH_TIMEOUT(w.stateModel()->epochCount() > epochsBefore + 1, 20000);

        QVERIFY(w.showDock("corrections"));
        QDockWidget *dock = w.dock("correctionsDock");
        QVERIFY(dock);
        auto *host = dock->findChild<QLineEdit *>("correctionsHost");
        auto *port = dock->findChild<QSpinBox *>("correctionsPort");
        auto *mount = dock->findChild<QLineEdit *>("correctionsMount");
        auto *user = dock->findChild<QLineEdit *>("correctionsUser");
        auto *password = dock->findChild<QLineEdit *>("correctionsPassword");
        auto *rememberBox = dock->findChild<QCheckBox *>("correctionsRememberPassword");
        auto *start = dock->findChild<QPushButton *>("correctionsStartStop");
        auto *statusLabel = dock->findChild<QLabel *>("correctionsStatus");
        QVERIFY(host && port && mount && user && password && rememberBox && start && statusLabel);
        const QString credentials = QString::fromLatin1(kSecretUser + ':' + typedPassword);
        host->setText(inHost ? credentials + QStringLiteral("@127.0.0.1")
                             : QStringLiteral("127.0.0.1"));
        port->setValue(caster.port());
        mount->setText("MOUNT");
        user->setText(QString::fromLatin1(kSecretUser));
        password->setText(QString::fromLatin1(typedPassword));
        QCOMPARE(password->echoMode(), QLineEdit::Password);
        if (rememberBox->isVisible()) rememberBox->setChecked(remember);
        QTest::mouseClick(start, Qt::LeftButton);
        QTRY_VERIFY2_WITH_TIMEOUT(statusLabel->text().contains(status),
                                  qPrintable(statusLabel->text()), 20000);
        if (status.startsWith("Receiving")) // a while of data into the receiver and the recording
            QTRY_VERIFY_WITH_TIMEOUT(next >= 5, 20000);
        if (inHost) QVERIFY(caster.connections == 0); // refused before anything started

        // Everything is written out as when the window closes.
        QTest::mouseClick(start, Qt::LeftButton);
        w.link()->stopRecording();
        w.saveLayout();
        window.settings.sync();
        QTest::qWait(200); // the keychain's answer, when one was asked

        // The host field shows what the user typed (as the password field does): not looked
        // at; every other place is.
        if (inHost) host->clear();
        for (const SecretForms &s : {SecretForms(), SecretForms(kSecretUser, typedPassword)}) {
            for (const QString &text : shownTexts(&w))
                QVERIFY2(s.foundIn(text.toUtf8()).isEmpty(), qPrintable(text));
            QStringList said;
            {
                QMutexLocker lock(&messagesLock);
                said = messages;
            }
            for (const QString &m : said) QVERIFY2(s.foundIn(m.toUtf8()).isEmpty(), qPrintable(m));
            const QStringList files = s.filesHolding(window.dir.path());
            QVERIFY2(files.isEmpty(), qPrintable(files.join('\n')));
        }
        QVERIFY(QFileInfo(window.settingsFile()).size() > 0);
        QVERIFY(QFileInfo(recording).size() > 0);
        // The host typed with credentials is not remembered either.
        QVERIFY(!window.settings.value("corrections/host").toString().contains('@'));
    }
};

QTEST_MAIN(TstCredentialsWindow)
#include "tst_credentials_window.moc"
