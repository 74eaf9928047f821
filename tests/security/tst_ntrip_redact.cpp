// ntrip/redact.h: the password, "user:password" and their Base64 masked in any text; a host
// typed as "user:password@caster" recognised and shown without them.
#include "ntrip/base64.h"
#include "ntrip/redact.h"

#include <QTest>

using namespace gnss::ntrip;

class TstNtripRedact : public QObject {
    Q_OBJECT
private slots:
    void credentialsAreMaskedWhereverTheyStand_data() {
        QTest::addColumn<QString>("user");
        QTest::addColumn<QString>("password");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        const std::string b64 = base64Encode("rover7:Pw-7zXkq93");
        QTest::newRow("the password") << "rover7"
                                      << "Pw-7zXkq93"
                                      << "bad Pw-7zXkq93!"
                                      << "bad ***!";
        QTest::newRow("user:password") << "rover7"
                                       << "Pw-7zXkq93"
                                       << "for rover7:Pw-7zXkq93@h"
                                       << "for ***@h";
        QTest::newRow("the Authorization header")
                << "rover7"
                << "Pw-7zXkq93" << QString::fromStdString("Authorization: Basic " + b64 + "\r\n")
                << "Authorization: Basic ***\r\n";
        QTest::newRow("the password's own Base64")
                << "rover7"
                << "Pw-7zXkq93" << QString::fromStdString("x " + base64Encode("Pw-7zXkq93") + " y")
                << "x *** y";
        QTest::newRow("twice") << "u"
                               << "secret"
                               << "secret secret"
                               << "*** ***";
        QTest::newRow("a short password: only with its user") << "u"
                                                              << "ab"
                                                              << "a table, u:ab"
                                                              << "a table, ***";
        QTest::newRow("no credentials: unchanged") << ""
                                                   << ""
                                                   << "Receiving"
                                                   << "Receiving";
        QTest::newRow("nothing of them: unchanged") << "rover7"
                                                    << "Pw-7zXkq93"
                                                    << "Mountpoint MOUNT not found"
                                                    << "Mountpoint MOUNT not found";
    }
    void credentialsAreMaskedWhereverTheyStand() {
        QFETCH(QString, user);
        QFETCH(QString, password);
        QFETCH(QString, text);
        QFETCH(QString, expected);
        QCOMPARE(QString::fromStdString(redactCredentials(text.toStdString(), user.toStdString(),
                                                          password.toStdString())),
                 expected);
    }

    void aHostWithUserInformation_data() {
        QTest::addColumn<QString>("host");
        QTest::addColumn<bool>("userInfo");
        QTest::addColumn<QString>("shown");
        QTest::newRow("a name") << "caster.example" << false << "caster.example";
        QTest::newRow("an IPv6 address") << "::1" << false << "::1";
        QTest::newRow("user:password@") << "u:pw@caster.example" << true << "***@caster.example";
        QTest::newRow("user@") << "u@caster.example" << true << "***@caster.example";
        QTest::newRow("an '@' in the password") << "u:p@w@caster" << true << "***@caster";
    }
    void aHostWithUserInformation() {
        QFETCH(QString, host);
        QFETCH(bool, userInfo);
        QFETCH(QString, shown);
        QCOMPARE(hasUserInfo(host.toStdString()), userInfo);
        QCOMPARE(QString::fromStdString(hostForDisplay(host.toStdString())), shown);
    }
};

QTEST_MAIN(TstNtripRedact)
#include "tst_ntrip_redact.moc"
