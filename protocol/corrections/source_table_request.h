#pragma once
// SourceTableRequest: one asynchronous request for a caster's source table (GET /), on its own
// connection. Ends with received(table) once ENDSOURCETABLE, the announced length or the end of
// the connection is reached with a table in hand, or failed(reason) in words (refused, 401,
// not a caster, no answer within the timeout). Credentials never appear in the reason.
#include "ntrip/chunked_decoder.h"
#include "ntrip/ntrip_request.h"
#include "ntrip/response_head.h"
#include "ntrip/source_table.h"

#include <QObject>
#include <QTcpSocket>
#include <QTimer>

namespace gnss::corrections {

struct SourceTableQuery {
    QString host;
    quint16 port = 2101;
    ntrip::NtripVersion version = ntrip::NtripVersion::V2;
    QString user; // some casters show more streams to known users
    QString password;
    int timeoutMs = 30000;
};

// What is sent to ask the caster of `query` for `mountpoint` (empty: for its source table).
ntrip::RequestTarget requestTarget(const SourceTableQuery &query, const QString &mountpoint = {});

// `text` with the password, "user:password" and its Base64 masked (ntrip/redact.h).
QString redactedText(const QString &text, const QString &user, const QString &password);
// A host as it may be shown: user information ("user:password@") masked.
QString displayHost(const QString &host);

class SourceTableRequest : public QObject {
    Q_OBJECT
public:
    explicit SourceTableRequest(SourceTableQuery query, QObject *parent = nullptr);
    ~SourceTableRequest() override;

    void start();
    void abort();
    // The reply head (which NTRIP revision answered).
    const ntrip::ResponseHead &reply() const { return reply_.head(); }

signals:
    void received(const gnss::ntrip::SourceTable &table);
    void failed(const QString &reason);

private:
    QString hostPort() const;
    void onReadyRead();
    void onDisconnected();
    void fail(const QString &reason);
    void finish();
    // The head is whole: a table follows, or the reason it does not.
    bool acceptHead();
    void takeBody(std::string_view body);

    SourceTableQuery query_;
    QTcpSocket socket_;
    QTimer timeout_;
    ntrip::ResponseHeadParser reply_;
    ntrip::ChunkedDecoder chunks_;
    ntrip::SourceTableParser table_;
    bool headAccepted_ = false;
    bool done_ = false;
    std::uint64_t bodyBytes_ = 0;
};

} // namespace gnss::corrections
