// gnss-cli ntrip never says a caster's credentials: run against the test caster with a
// distinctive password, in every outcome (data, source table, nearest mountpoint, a refused
// password, a caster that echoes the credentials back, a refused connection, credentials typed
// into --caster or as an option), standard output, standard error and the --out file hold
// neither the password, nor "user:password", nor their Base64 (the Authorization header's), nor
// the user name.
#include "cli_run.h"
#include "ntrip_cli_run.h"
#include "rtcm_fixtures.h"
#include "secret_scan.h"
#include "test_caster.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace corrections_test;
using gnss::test::kSecretPassword;
using gnss::test::kSecretUser;
using gnss::test::Run;
using gnss::test::SecretForms;

namespace {

// Runs gnss-cli in `dir` with the password in TEST_NTRIP_PW while the test's event loop serves
// the caster; `feed` is called every 100 ms.
Run cli(const QStringList &args, const QByteArray &password, const QString &dir,
        const std::function<void()> &feed) {
    return gnss::test::runNtripCli(args, QString::fromLatin1(password), feed, dir);
}

// What a caster that echoes the request's credentials back answers (some proxies and broken
// casters put the Authorization header's value in their refusal).
QByteArray echoingReply(bool dataRequest) {
    const SecretForms s;
    const QByteArray words = "Forbidden for " + s.forms[1] + " (Basic " + s.forms[2] + ")";
    return dataRequest ? "HTTP/1.1 403 " + words + "\r\nContent-Length: 0\r\n\r\n"
                       : "HTTP/1.1 400 " + words + "\r\nContent-Length: 0\r\n\r\n";
}

} // namespace

class TstCredentialsCli : public QObject {
    Q_OBJECT
private slots:
    void noCredentialInAnythingGnssCliSays_data() {
        QTest::addColumn<QStringList>("args");    // CASTER: the caster's host:port
        QTest::addColumn<QByteArray>("password"); // what TEST_NTRIP_PW holds
        QTest::addColumn<QByteArray>("rawReply"); // the caster's one answer (empty: a caster's)
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("words"); // said on standard error

        const QStringList auth{"--user", QString::fromLatin1(kSecretUser), "--password-env",
                               "TEST_NTRIP_PW"};
        const QByteArray pw = kSecretPassword;
        for (const char *v : {"1", "2"}) {
            const QStringList version{"--ntrip-version", v};
            const QByteArray tag = QByteArray(" (NTRIP ") + v + ")";
            QTest::newRow("data, written to a file" + tag)
                    << QStringList{"--mount", "MOUNT", "--out", "rtcm.bin", "--duration", "3"} +
                               auth + version
                    << pw << QByteArray() << 0 << "Receiving RTCM from 127.0.0.1:";
            QTest::newRow("the wrong password" + tag)
                    << QStringList{"--mount", "MOUNT"} + auth + version
                    << QByteArray("Wrong-9q8w7e-pass") << QByteArray() << 1
                    << "refused the user name or password";
        }
        QTest::newRow("the source table") << QStringList{"--sourcetable"} + auth << pw
                                          << QByteArray() << 0 << "\"streams\":3";
        QTest::newRow("the nearest mountpoint")
                << QStringList{"--nearest", "--gga", "55.75,37.62,150", "--duration", "3"} + auth
                << pw << QByteArray() << 0 << "nearest RTCM 3 mountpoint: MOUNT";
        QTest::newRow("a caster that echoes them, for data")
                << QStringList{"--mount", "MOUNT", "--duration", "3"} + auth << pw
                << echoingReply(true) << 1 << "Forbidden for *** (Basic ***)";
        QTest::newRow("a caster that echoes them, for its table")
                << QStringList{"--sourcetable"} + auth << pw << echoingReply(false) << 1
                << "Forbidden for *** (Basic ***)";
        QTest::newRow("in --caster as user:password@host")
                << QStringList{"--mount", "MOUNT", "--caster-with-credentials"} << pw
                << QByteArray() << 2 << "--caster takes HOST:PORT only";
        QTest::newRow("in --caster as a URL")
                << QStringList{"--mount", "MOUNT", "--caster-as-url"} << pw << QByteArray() << 2
                << "--caster takes HOST:PORT only";
        QTest::newRow("as --password on the command line")
                << QStringList{"--mount", "MOUNT", "--password", QString::fromLatin1(pw)} << pw
                << QByteArray() << 2 << "unknown option --password";
        QTest::newRow("as --password=... on the command line")
                << QStringList{"--mount", "MOUNT", "--password=" + QString::fromLatin1(pw)} << pw
                << QByteArray() << 2 << "unknown option --password";
        QTest::newRow("nobody listening")
                << QStringList{"--mount", "MOUNT", "--duration", "2", "--closed-port"} + auth << pw
                << QByteArray() << 1 << "refused the connection";
    }
    void noCredentialInAnythingGnssCliSays() {
        QFETCH(QStringList, args);
        QFETCH(QByteArray, password);
        QFETCH(QByteArray, rawReply);
        QFETCH(int, exitCode);
        QFETCH(QString, words);

        TstCaster caster;
        caster.user = kSecretUser;
        caster.password = kSecretPassword;
        caster.rawReply = rawReply;
        QVERIFY(caster.listen());
        const QString hostPort = QStringLiteral("127.0.0.1:%1").arg(caster.port());
        const QString credentials = QString::fromLatin1(kSecretUser + ':' + kSecretPassword);
        QString where = hostPort;
        if (args.removeAll("--caster-with-credentials")) where = credentials + '@' + hostPort;
        if (args.removeAll("--caster-as-url"))
            where = "ntrip://" + credentials + '@' + hostPort + "/MOUNT";
        if (args.removeAll("--closed-port"))
            where = QStringLiteral("127.0.0.1:%1").arg(closedPort());
        const QList<QByteArray> epochs = baseEpochs(40);
        int next = 0;
        auto feed = [&] {
            if (caster.streamingClients() > 0 && next < epochs.size()) caster.send(epochs[next++]);
        };

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const Run r =
                cli(QStringList{"ntrip", "--caster", where} + args, password, dir.path(), feed);
        QVERIFY2(r.exitCode == exitCode, r.err.constData());
        QVERIFY2(r.err.contains(words.toUtf8()), r.err.constData());

        // Nothing it said or wrote holds them: not the caster's, not the one it was given.
        const SecretForms secrets;
        const SecretForms given(kSecretUser, password);
        for (const SecretForms *s : {&secrets, &given}) {
            QVERIFY2(s->foundIn(r.out).isEmpty(), r.out.left(2000).constData());
            QVERIFY2(s->foundIn(r.err).isEmpty(), r.err.constData());
            const QStringList files = s->filesHolding(dir.path());
            QVERIFY2(files.isEmpty(), qPrintable(files.join('\n')));
        }
        // Nor the user name: gnss-cli has no reason to say it.
        QVERIFY2(!r.out.contains(kSecretUser) && !r.err.contains(kSecretUser), r.err.constData());
        // What went to the caster did carry them, in the Authorization header and only there.
        if (exitCode != 2 && where == hostPort && rawReply.isEmpty() &&
            password == kSecretPassword) {
            QVERIFY(!caster.requests.isEmpty());
            for (const QByteArray &request : caster.requests) {
                QVERIFY(request.contains("Authorization: Basic " + secrets.forms[2] + "\r\n"));
                QVERIFY(!request.contains(kSecretPassword));
            }
        }
        if (args.contains("--out")) QVERIFY(QFile(dir.filePath("rtcm.bin")).size() > 0);
    }
};

QTEST_MAIN(TstCredentialsCli)
#include "tst_credentials_cli.moc"
