// The reply head parser: every kind of caster reply is recognised, the body passes through
// byte-exact, and neither depends on where the reply is cut into pieces.
#include "ntrip/response_head.h"

#include <QTest>

#include <random>

using namespace gnss::ntrip;

Q_DECLARE_METATYPE(ReplyKind)
Q_DECLARE_METATYPE(ReplyStyle)

namespace {

struct Parsed {
    ResponseHead head;
    std::string body;
    bool statusKnown = false;
};

// `reply` fed in pieces cut at `cuts` (ascending positions), then the connection closes.
Parsed parse(const QByteArray &reply, const QList<int> &cuts = {}) {
    ResponseHeadParser p;
    Parsed r;
    int from = 0;
    for (int c : cuts + QList<int>{int(reply.size())}) {
        p.feed(std::string_view(reply.constData() + from, std::size_t(c - from)), r.body);
        from = c;
    }
    r.statusKnown = p.statusKnown();
    p.finish();
    r.head = p.head();
    return r;
}

const QByteArray kFrame = QByteArray::fromHex("d300133ed7d30202980edeef34b4bd62ac0941986f33360b98");

} // namespace

class TstNtripResponseHead : public QObject {
    Q_OBJECT
private slots:
    void eachReplyIsRecognised_data() {
        QTest::addColumn<QByteArray>("reply");
        QTest::addColumn<ReplyKind>("kind");
        QTest::addColumn<ReplyStyle>("style");
        QTest::addColumn<int>("code");
        QTest::addColumn<bool>("chunked");
        QTest::addColumn<QByteArray>("body");
        QTest::addColumn<QString>("revision");

        QTest::newRow("NTRIP 1 data: ICY then RTCM at once")
                << ("ICY 200 OK\r\n" + kFrame) << ReplyKind::Data << ReplyStyle::Icy << 200 << false
                << kFrame << "NTRIP 1 (ICY)";
        QTest::newRow("NTRIP 1 data: ICY, header lines, blank line, RTCM")
                << ("ICY 200 OK\r\nServer: Caster/1.0\r\nDate: today\r\n\r\n" + kFrame)
                << ReplyKind::Data << ReplyStyle::Icy << 200 << false << kFrame << "NTRIP 1 (ICY)";
        QTest::newRow("NTRIP 1 data: ICY then NMEA text is body, not headers")
                << QByteArray("ICY 200 OK\r\n$GPGGA,1,2*00\r\n") << ReplyKind::Data
                << ReplyStyle::Icy << 200 << false << QByteArray("$GPGGA,1,2*00\r\n")
                << "NTRIP 1 (ICY)";
        QTest::newRow("NTRIP 1 data: ICY then a text line without colon is body")
                << QByteArray("ICY 200 OK\r\nhello world\r\n") << ReplyKind::Data << ReplyStyle::Icy
                << 200 << false << QByteArray("hello world\r\n") << "NTRIP 1 (ICY)";
        QTest::newRow("NTRIP 2 data, chunked")
                << ("HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\nContent-Type: gnss/data\r\n"
                    "Transfer-Encoding: chunked\r\n\r\n19\r\n" +
                    kFrame + "\r\n")
                << ReplyKind::Data << ReplyStyle::Http << 200 << true
                << ("19\r\n" + kFrame + "\r\n") << "NTRIP 2 (HTTP/1.1)";
        QTest::newRow("NTRIP 2 data, not chunked, header names in any case")
                << ("HTTP/1.1 200 OK\r\nntrip-version: Ntrip/2.0\r\ncontent-type: GNSS/Data; "
                    "x=1\r\n\r\n" +
                    kFrame)
                << ReplyKind::Data << ReplyStyle::Http << 200 << false << kFrame
                << "NTRIP 2 (HTTP/1.1)";
        QTest::newRow("HTTP 200 without a content type is taken as data")
                << ("HTTP/1.0 200 OK\r\n\r\n" + kFrame) << ReplyKind::Data << ReplyStyle::Http
                << 200 << false << kFrame << "HTTP/1.0";
        QTest::newRow("NTRIP 1 source table")
                << QByteArray("SOURCETABLE 200 OK\r\nServer: RTKLIB 2.4.3 b34\r\nContent-Type: "
                              "text/plain\r\nContent-Length: 16\r\n\r\nENDSOURCETABLE\r\n")
                << ReplyKind::SourceTable << ReplyStyle::SourceTable << 200 << false
                << QByteArray("ENDSOURCETABLE\r\n") << "NTRIP 1 (SOURCETABLE)";
        QTest::newRow("NTRIP 2 source table")
                << QByteArray("HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\nContent-Type: "
                              "gnss/sourcetable\r\n\r\nSTR;A;\r\n")
                << ReplyKind::SourceTable << ReplyStyle::Http << 200 << false
                << QByteArray("STR;A;\r\n") << "NTRIP 2 (HTTP/1.1)";
        QTest::newRow("401 as RTKLIB sends it: no blank line, then the connection closes")
                << QByteArray("HTTP/1.0 401 Unauthorized\r\n") << ReplyKind::Unauthorized
                << ReplyStyle::Http << 401 << false << QByteArray() << "HTTP/1.0";
        QTest::newRow("401 without even CR LF before the close")
                << QByteArray("HTTP/1.0 401 Unauthorized") << ReplyKind::Unauthorized
                << ReplyStyle::Http << 401 << false << QByteArray() << "HTTP/1.0";
        QTest::newRow("NTRIP 2 401 with headers and a page")
                << QByteArray("HTTP/1.1 401 Unauthorized\r\nNtrip-Version: Ntrip/2.0\r\n"
                              "WWW-Authenticate: Basic realm=\"/M\"\r\n\r\n<html/>")
                << ReplyKind::Unauthorized << ReplyStyle::Http << 401 << false
                << QByteArray("<html/>") << "NTRIP 2 (HTTP/1.1)";
        QTest::newRow("404") << QByteArray("HTTP/1.1 404 Not Found\r\n\r\n") << ReplyKind::NotFound
                             << ReplyStyle::Http << 404 << false << QByteArray() << "HTTP/1.1";
        QTest::newRow("503 is another status")
                << QByteArray("HTTP/1.1 503 Service Unavailable\r\n\r\n") << ReplyKind::OtherStatus
                << ReplyStyle::Http << 503 << false << QByteArray() << "HTTP/1.1";
        QTest::newRow("an ERROR line from an old caster")
                << QByteArray("ERROR - Bad Password\r\n") << ReplyKind::CasterError
                << ReplyStyle::Error << 0 << false << QByteArray() << "NTRIP 1 (ERROR line)";
        QTest::newRow("a web server's page")
                << QByteArray("HTTP/1.1 200 OK\r\nContent-Type: text/html\r\n\r\n<html>")
                << ReplyKind::UnexpectedContent << ReplyStyle::Http << 200 << false
                << QByteArray("<html>") << "HTTP/1.1";
        QTest::newRow("binary noise") << kFrame << ReplyKind::NotNtrip << ReplyStyle::Unknown << 0
                                      << false << QByteArray() << "unknown";
        QTest::newRow("another protocol's banner")
                << QByteArray("SSH-2.0-OpenSSH_9.2\r\n") << ReplyKind::NotNtrip
                << ReplyStyle::Unknown << 0 << false << QByteArray() << "unknown";
        QTest::newRow("a status line without a code")
                << QByteArray("HTTP/1.1 OK\r\n\r\n") << ReplyKind::NotNtrip << ReplyStyle::Http << 0
                << false << QByteArray() << "HTTP/1.1";
    }
    void eachReplyIsRecognised() {
        QFETCH(QByteArray, reply);
        QFETCH(ReplyKind, kind);
        QFETCH(ReplyStyle, style);
        QFETCH(int, code);
        QFETCH(bool, chunked);
        QFETCH(QByteArray, body);
        QFETCH(QString, revision);
        const Parsed r = parse(reply);
        QCOMPARE(r.head.kind, kind);
        QCOMPARE(r.head.style, style);
        QCOMPARE(r.head.statusCode, code);
        QCOMPARE(r.head.chunked, chunked);
        QCOMPARE(QByteArray::fromStdString(r.body), body);
        QCOMPARE(QString::fromStdString(r.head.revisionText()), revision);
    }

    void theHeadAndBodyDoNotDependOnChunking_data() { eachReplyIsRecognised_data(); }
    void theHeadAndBodyDoNotDependOnChunking() {
        QFETCH(QByteArray, reply);
        const Parsed whole = parse(reply);
        for (int cut = 1; cut < reply.size(); ++cut) {
            for (int second = cut + 1; second <= std::min<int>(cut + 3, reply.size()); ++second) {
                const Parsed r = parse(reply, second < reply.size() ? QList<int>{cut, second}
                                                                    : QList<int>{cut});
                QCOMPARE(r.head.kind, whole.head.kind);
                QCOMPARE(r.head.statusCode, whole.head.statusCode);
                QCOMPARE(r.head.chunked, whole.head.chunked);
                QCOMPARE(r.head.contentType, whole.head.contentType);
                QCOMPARE(r.body, whole.body);
            }
        }
        QList<int> everyByte;
        for (int i = 1; i < reply.size(); ++i) everyByte.append(i);
        const Parsed bytewise = parse(reply, everyByte);
        QCOMPARE(bytewise.head.kind, whole.head.kind);
        QCOMPARE(bytewise.body, whole.body);
    }

    void theStatusIsKnownBeforeTheHeadEnds() {
        ResponseHeadParser p;
        std::string body;
        p.feed("HTTP/1.1 401 Unauthorized\r\nServer: x\r\n", body);
        QVERIFY(p.statusKnown());
        QVERIFY(!p.headComplete());
        QCOMPARE(p.head().kind, ReplyKind::Unauthorized);
    }

    void headersAreKept() {
        const Parsed r =
                parse("HTTP/1.1 200 OK\r\nContent-Type: gnss/sourcetable\r\n"
                      "Content-Length: 1234\r\nbroken line\r\nServer: NTRIP Caster\r\n\r\n");
        QCOMPARE(r.head.contentLength.value_or(0), std::uint64_t(1234));
        QCOMPARE(r.head.badHeaderLines, 1u);
        QCOMPARE(int(r.head.headers.size()), 3);
        QCOMPARE(r.head.headers[2].second, std::string("NTRIP Caster"));
    }

    // The content type is shown in messages ("answered with %1"): a caster's control bytes in
    // it (a terminal escape) are '?', as in every other text of the head (found by tests/fuzz
    // fuzz_ntrip_response).
    void theContentTypeIsPrintable() {
        const Parsed r = parse("HTTP/1.1 200 OK\r\nContent-Type: Text/\x1b[31mHTML\xff\r\n\r\n");
        QCOMPARE(r.head.kind, ReplyKind::UnexpectedContent);
        QCOMPARE(r.head.contentType, std::string("text/?[31mhtml?"));
    }

    void aHeadThatNeverEndsIsNotNtrip() {
        QByteArray reply = "HTTP/1.1 200 OK\r\n";
        while (reply.size() < 20000) reply += "X-Filler: aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\r\n";
        QCOMPARE(parse(reply).head.kind, ReplyKind::NotNtrip);
        QCOMPARE(parse("HTTP/1.1 200 OK\r\nX: " + QByteArray(5000, 'a')).head.kind,
                 ReplyKind::NotNtrip);
        QCOMPARE(parse("HTTP/1.1 " + QByteArray(5000, '2')).head.kind, ReplyKind::NotNtrip);
    }

    void nothingAtAllStaysIncomplete() {
        QCOMPARE(parse(QByteArray()).head.kind, ReplyKind::Incomplete);
    }

    void randomRepliesNeverCrash() {
        std::mt19937 rng(7);
        const QList<QByteArray> starts = {"ICY 200 OK\r\n", "HTTP/1.1 200 OK\r\n",
                                          "SOURCETABLE 200 OK\r\n", "", "HTTP/1.0 "};
        for (int i = 0; i < 3000; ++i) {
            QByteArray reply = starts[int(rng() % starts.size())];
            const int n = int(rng() % 300);
            for (int k = 0; k < n; ++k) {
                const char pick = "\r\n: ;aZ0\xd3\x00"[rng() % 11];
                reply.append(rng() % 3 ? pick : char(rng() & 0xFF));
            }
            QList<int> cuts;
            for (int c = 1; c < reply.size(); c += 1 + int(rng() % 17)) cuts.append(c);
            const Parsed a = parse(reply), b = parse(reply, cuts);
            QCOMPARE(a.head.kind, b.head.kind);
            QCOMPARE(a.body, b.body);
        }
    }
};

QTEST_APPLESS_MAIN(TstNtripResponseHead)
#include "tst_ntrip_response_head.moc"
