// Requests: NTRIP 1 and 2 byte for byte, the source table request, Basic authentication with
// our own Base64 (RFC 4648 vectors), and fields that would break a request refused.
#include "ntrip/base64.h"
#include "ntrip/ntrip_request.h"

#include <QTest>

#include <random>

using namespace gnss::ntrip;

Q_DECLARE_METATYPE(gnss::ntrip::RequestTarget)

class TstNtripRequest : public QObject {
    Q_OBJECT
private slots:
    void base64MatchesRfc4648_data() {
        QTest::addColumn<QByteArray>("plain");
        QTest::addColumn<QByteArray>("encoded");
        QTest::newRow("empty") << QByteArray() << QByteArray();
        QTest::newRow("f") << QByteArray("f") << QByteArray("Zg==");
        QTest::newRow("fo") << QByteArray("fo") << QByteArray("Zm8=");
        QTest::newRow("foo") << QByteArray("foo") << QByteArray("Zm9v");
        QTest::newRow("foob") << QByteArray("foob") << QByteArray("Zm9vYg==");
        QTest::newRow("fooba") << QByteArray("fooba") << QByteArray("Zm9vYmE=");
        QTest::newRow("foobar") << QByteArray("foobar") << QByteArray("Zm9vYmFy");
        QTest::newRow("user:pass") << QByteArray("user:pass") << QByteArray("dXNlcjpwYXNz");
        QTest::newRow("high bytes") << QByteArray("\xff\xfe\xfd\x00", 4) << QByteArray("//79AA==");
    }
    void base64MatchesRfc4648() {
        QFETCH(QByteArray, plain);
        QFETCH(QByteArray, encoded);
        QCOMPARE(QByteArray::fromStdString(base64Encode(plain.toStdString())), encoded);
        QCOMPARE(QByteArray::fromStdString(base64Decode(encoded.toStdString()).value_or("?")),
                 plain);
    }

    void base64AgreesWithQtOnRandomBytes() {
        std::mt19937 rng(3);
        for (int i = 0; i < 500; ++i) {
            QByteArray b;
            for (int k = int(rng() % 40); k > 0; --k) b.append(char(rng() & 0xFF));
            QCOMPARE(QByteArray::fromStdString(base64Encode(b.toStdString())), b.toBase64());
        }
    }

    void badBase64IsRefused_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("length not a multiple of 4") << QByteArray("Zm9");
        QTest::newRow("foreign character") << QByteArray("Zm9*");
        QTest::newRow("padding in the middle") << QByteArray("Zg==Zm9v");
        QTest::newRow("padding first") << QByteArray("=m9v");
    }
    void badBase64IsRefused() {
        QFETCH(QByteArray, text);
        QVERIFY(!base64Decode(text.toStdString()));
    }

    // NTRIP 1 as RTKLIB's caster expects it; NTRIP 2 with its Host, version and Connection: close.
    void mountpointRequestIsByteForByte_data() {
        QTest::addColumn<RequestTarget>("target");
        QTest::addColumn<QByteArray>("request");
        QTest::newRow("NTRIP 1") << RequestTarget{"127.0.0.1",      2101,   "MOUNT",
                                                  NtripVersion::V1, "user", "pass"}
                                 << QByteArray("GET /MOUNT HTTP/1.0\r\n"
                                               "User-Agent: NTRIP GNSSWorkbench/0.1\r\n"
                                               "Authorization: Basic dXNlcjpwYXNz\r\n"
                                               "\r\n");
        QTest::newRow("NTRIP 2") << RequestTarget{"caster.example.org", 2102,    "VRS_RTCM3",
                                                  NtripVersion::V2,     "rover", "p:w"}
                                 << QByteArray("GET /VRS_RTCM3 HTTP/1.1\r\n"
                                               "Host: caster.example.org:2102\r\n"
                                               "Ntrip-Version: Ntrip/2.0\r\n"
                                               "User-Agent: NTRIP GNSSWorkbench/0.1\r\n"
                                               "Authorization: Basic cm92ZXI6cDp3\r\n"
                                               "Connection: close\r\n"
                                               "\r\n");
    }
    void mountpointRequestIsByteForByte() {
        QFETCH(RequestTarget, target);
        QFETCH(QByteArray, request);
        std::string error;
        QCOMPARE(QByteArray::fromStdString(buildRequest(target, error)), request);
        QVERIFY(error.empty());
    }

    void sourceTableRequestAsksForTheRoot_data() {
        QTest::addColumn<int>("version");
        QTest::addColumn<QByteArray>("request");
        QTest::newRow("NTRIP 1") << 1
                                 << QByteArray("GET / HTTP/1.0\r\n"
                                               "User-Agent: NTRIP GNSSWorkbench/0.1\r\n\r\n");
        QTest::newRow("NTRIP 2") << 2
                                 << QByteArray("GET / HTTP/1.1\r\nHost: [::1]:2101\r\n"
                                               "Ntrip-Version: Ntrip/2.0\r\n"
                                               "User-Agent: NTRIP GNSSWorkbench/0.1\r\n"
                                               "Connection: close\r\n\r\n");
    }
    void sourceTableRequestAsksForTheRoot() {
        QFETCH(int, version);
        QFETCH(QByteArray, request);
        RequestTarget t;
        t.host = "::1";
        t.version = NtripVersion(version);
        std::string error;
        QCOMPARE(QByteArray::fromStdString(buildRequest(t, error)), request);
    }

    void fieldsThatWouldBreakTheRequestAreRefused_data() {
        QTest::addColumn<QString>("mount");
        QTest::addColumn<QString>("user");
        QTest::addColumn<QString>("password");
        QTest::addColumn<QString>("why");
        QTest::newRow("a mountpoint with CR LF") << "M\r\nX-Evil: 1"
                                                 << ""
                                                 << ""
                                                 << "control characters";
        QTest::newRow("a mountpoint with a space") << "M N"
                                                   << ""
                                                   << ""
                                                   << "' '";
        QTest::newRow("a mountpoint with a query") << "M?x=1"
                                                   << ""
                                                   << ""
                                                   << "'?'";
        QTest::newRow("a mountpoint with its slash") << "/M"
                                                     << ""
                                                     << ""
                                                     << "leading '/'";
        QTest::newRow("a user name with a colon") << "M"
                                                  << "a:b"
                                                  << "x"
                                                  << "':'";
        QTest::newRow("a password with a line feed") << "M"
                                                     << "a"
                                                     << "x\ny"
                                                     << "control";
    }
    void fieldsThatWouldBreakTheRequestAreRefused() {
        QFETCH(QString, mount);
        QFETCH(QString, user);
        QFETCH(QString, password);
        QFETCH(QString, why);
        RequestTarget t;
        t.host = "h";
        t.mountpoint = mount.toStdString();
        t.user = user.toStdString();
        t.password = password.toStdString();
        std::string error;
        QVERIFY(buildRequest(t, error).empty());
        QVERIFY2(QString::fromStdString(error).contains(why), error.c_str());
        QVERIFY(error.find(password.toStdString()) == std::string::npos || password.isEmpty());
    }
};

QTEST_APPLESS_MAIN(TstNtripRequest)
#include "tst_ntrip_request.moc"
