// The caster's request parser: NTRIP 1 and 2 heads with and without credentials, malformed ones
// (no end within the cap, a bad request line, bad Base64, another method than GET), and the
// same result whatever the chunking, one byte at a time included.
#include "ntrip/caster_request.h"

#include <QTest>

using namespace gnss::ntrip;
using State = CasterRequestParser::State;

namespace {

struct Seen {
    State state;
    QByteArray mount, user, password, agent, host, gga, reason, rest;
    int version = 0, status = 0;
    bool auth = false;
    bool operator==(const Seen &o) const {
        return state == o.state && mount == o.mount && user == o.user && password == o.password &&
               agent == o.agent && host == o.host && gga == o.gga && reason == o.reason &&
               rest == o.rest && version == o.version && status == o.status && auth == o.auth;
    }
};

Seen seenOf(const CasterRequestParser &p) {
    const CasterRequest &r = p.request();
    auto b = [](const std::string &s) { return QByteArray::fromStdString(s); };
    return {p.state(),      b(r.mountpoint), b(r.user),      b(r.password),
            b(r.userAgent), b(r.host),       b(r.ntripGga),  b(p.reason()),
            b(p.rest()),    int(r.version),  p.statusCode(), r.hasAuthorization};
}

Seen feedInPieces(const QByteArray &bytes, int piece) {
    CasterRequestParser p;
    for (qsizetype i = 0; i < bytes.size(); i += piece)
        p.feed(std::string_view(bytes.constData() + i,
                                std::size_t(std::min<qsizetype>(piece, bytes.size() - i))));
    return seenOf(p);
}

} // namespace

class TstCasterRequest : public QObject {
    Q_OBJECT
private slots:
    void heads_data() {
        QTest::addColumn<QByteArray>("head");
        QTest::addColumn<int>("state");
        QTest::addColumn<QByteArray>("mount");
        QTest::addColumn<int>("version");
        QTest::addColumn<QByteArray>("user");
        QTest::addColumn<QByteArray>("password");
        QTest::addColumn<int>("status");

        const int complete = int(State::Complete), malformed = int(State::Malformed);
        QTest::newRow("NTRIP 1 with credentials")
                << QByteArray("GET /BASE HTTP/1.0\r\nUser-Agent: NTRIP RTKLIB/2.4.3\r\n"
                              "Authorization: Basic dXNlcjpwYXNz\r\n\r\n")
                << complete << QByteArray("BASE") << 1 << QByteArray("user") << QByteArray("pass")
                << 0;
        QTest::newRow("NTRIP 1 without credentials")
                << QByteArray("GET /BASE HTTP/1.0\r\nUser-Agent: NTRIP x\r\n\r\n") << complete
                << QByteArray("BASE") << 1 << QByteArray() << QByteArray() << 0;
        QTest::newRow("NTRIP 2 with credentials")
                << QByteArray("GET /VRS HTTP/1.1\r\nHost: 127.0.0.1:2101\r\n"
                              "Ntrip-Version: Ntrip/2.0\r\nUser-Agent: NTRIP x\r\n"
                              "Authorization: Basic cm92ZXI6cDp3\r\nConnection: close\r\n\r\n")
                << complete << QByteArray("VRS") << 2 << QByteArray("rover") << QByteArray("p:w")
                << 0;
        QTest::newRow("NTRIP 2 source table, bare LFs")
                << QByteArray("GET / HTTP/1.1\nntrip-version: Ntrip/2.0\n\n") << complete
                << QByteArray() << 2 << QByteArray() << QByteArray() << 0;
        QTest::newRow("a query is not part of the mountpoint")
                << QByteArray("GET /BASE?x=1 HTTP/1.0\r\n\r\n") << complete << QByteArray("BASE")
                << 1 << QByteArray() << QByteArray() << 0;
        QTest::newRow("no end within the cap")
                << QByteArray("GET /BASE HTTP/1.0\r\n") + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n" + QByteArray("X-Filler: ") +
                           QByteArray(1000, 'a') + "\r\n"
                << malformed << QByteArray("BASE") << 1 << QByteArray() << QByteArray() << 400;
        QTest::newRow("a line over the cap")
                << QByteArray("GET /") + QByteArray(3000, 'A') << malformed << QByteArray() << 1
                << QByteArray() << QByteArray() << 400;
        QTest::newRow("a request line of two words")
                << QByteArray("GET /BASE\r\n\r\n") << malformed << QByteArray() << 1 << QByteArray()
                << QByteArray() << 400;
        QTest::newRow("HTTP/2") << QByteArray("GET /BASE HTTP/2\r\n\r\n") << malformed
                                << QByteArray() << 1 << QByteArray() << QByteArray() << 400;
        QTest::newRow("no leading slash")
                << QByteArray("GET BASE HTTP/1.0\r\n\r\n") << malformed << QByteArray() << 1
                << QByteArray() << QByteArray() << 400;
        QTest::newRow("bad Base64")
                << QByteArray("GET /BASE HTTP/1.0\r\nAuthorization: Basic dXNlcjpwYXN*\r\n\r\n")
                << malformed << QByteArray("BASE") << 1 << QByteArray() << QByteArray() << 400;
        QTest::newRow("Base64 without ':'")
                << QByteArray("GET /BASE HTTP/1.0\r\nAuthorization: Basic dXNlcg==\r\n\r\n")
                << malformed << QByteArray("BASE") << 1 << QByteArray() << QByteArray() << 400;
        QTest::newRow("a header without ':'")
                << QByteArray("GET /BASE HTTP/1.0\r\nUser-Agent NTRIP\r\n\r\n") << malformed
                << QByteArray("BASE") << 1 << QByteArray() << QByteArray() << 400;
        QTest::newRow("POST") << QByteArray("POST /BASE HTTP/1.1\r\n\r\n") << malformed
                              << QByteArray("BASE") << 1 << QByteArray() << QByteArray() << 405;
        QTest::newRow("an NTRIP 1 SOURCE upload")
                << QByteArray("SOURCE letmein /BASE\r\nSource-Agent: NTRIP x\r\n\r\n") << malformed
                << QByteArray() << 1 << QByteArray() << QByteArray() << 400;
    }
    void heads() {
        QFETCH(QByteArray, head);
        QFETCH(int, state);
        QFETCH(QByteArray, mount);
        QFETCH(int, version);
        QFETCH(QByteArray, user);
        QFETCH(QByteArray, password);
        QFETCH(int, status);
        const Seen whole = feedInPieces(head, int(head.size()) + 1);
        QCOMPARE(int(whole.state), state);
        QCOMPARE(whole.mount, mount);
        QCOMPARE(whole.version, version);
        QCOMPARE(whole.user, user);
        QCOMPARE(whole.password, password);
        QCOMPARE(whole.status, status);
        QCOMPARE(whole.reason.isEmpty(), state != int(State::Malformed));
        for (int piece : {1, 2, 3, 7, 64})
            QVERIFY2(feedInPieces(head, piece) == whole, qPrintable(QString::number(piece)));
    }

    void aHeadCutShortNeedsMore() {
        CasterRequestParser p;
        QCOMPARE(p.feed("GET /BASE HTTP/1.0\r\nUser-Agent: NTRIP x\r\n"), State::NeedMore);
        QCOMPARE(p.feed("\r"), State::NeedMore);
        QCOMPARE(p.feed("\n"), State::Complete);
    }

    void headersAreRead() {
        const auto p = parseCasterRequest("GET /BASE HTTP/1.1\r\nHOST: caster:2101\r\n"
                                          "user-agent: NTRIP RTKLIB/2.4.3\r\n"
                                          "Ntrip-GGA: $GPGGA,1*00\r\n\r\n$GPGGA,after*00\r\n");
        QCOMPARE(p.state(), State::Complete);
        QCOMPARE(p.request().host, std::string("caster:2101"));
        QCOMPARE(p.request().userAgent, std::string("NTRIP RTKLIB/2.4.3"));
        QCOMPARE(p.request().ntripGga, std::string("$GPGGA,1*00"));
        QCOMPARE(p.request().version, NtripVersion::V1); // HTTP/1.1 without Ntrip-Version
        QCOMPARE(p.rest(), std::string("$GPGGA,after*00\r\n"));
    }

    void anotherSchemeGivesNoUser() {
        const auto p =
                parseCasterRequest("GET /BASE HTTP/1.1\r\nAuthorization: Digest x=1\r\n\r\n");
        QCOMPARE(p.state(), State::Complete);
        QVERIFY(p.request().hasAuthorization);
        QCOMPARE(p.request().authScheme, std::string("Digest"));
        QVERIFY(p.request().user.empty());
    }

    void theHeadCapHolds() {
        CasterRequestParser p;
        const std::string line = "X-A: " + std::string(100, 'b') + "\r\n";
        p.feed("GET / HTTP/1.0\r\n");
        for (int i = 0; i < 200 && p.state() == State::NeedMore; ++i) p.feed(line);
        QCOMPARE(p.state(), State::Malformed);
        QVERIFY(p.headBytes() <= CasterRequestParser::kMaxHead + 1);
    }
};

QTEST_APPLESS_MAIN(TstCasterRequest)
#include "tst_caster_request.moc"
