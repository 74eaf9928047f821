#include "corrections/source_table_request.h"

#include "corrections/correction_source.h"
#include "ntrip/redact.h"

namespace gnss::corrections {

ntrip::RequestTarget requestTarget(const SourceTableQuery &query, const QString &mountpoint) {
    ntrip::RequestTarget t;
    t.host = query.host.toStdString();
    t.port = query.port;
    t.mountpoint = mountpoint.toStdString();
    t.version = query.version;
    t.user = query.user.toStdString();
    t.password = query.password.toStdString();
    return t;
}

QString redactedText(const QString &text, const QString &user, const QString &password) {
    if (user.isEmpty() && password.isEmpty()) return text;
    return QString::fromStdString(ntrip::redactCredentials(text.toStdString(), user.toStdString(),
                                                           password.toStdString()));
}

QString displayHost(const QString &host) {
    return QString::fromStdString(ntrip::hostForDisplay(host.toStdString()));
}

SourceTableRequest::SourceTableRequest(SourceTableQuery query, QObject *parent)
    : QObject(parent), query_(std::move(query)) {
    timeout_.setSingleShot(true);
    connect(&timeout_, &QTimer::timeout, this, [this] {
        fail(tr("No source table from %1 within %2 s")
                     .arg(hostPort())
                     .arg((query_.timeoutMs + 999) / 1000));
    });
    connect(&socket_, &QTcpSocket::connected, this, [this] {
        std::string error;
        const std::string request = ntrip::buildRequest(requestTarget(query_), error);
        if (request.empty())
            return fail(tr("Cannot ask %1 for its source table: %2")
                                .arg(hostPort(), QString::fromStdString(error)));
        socket_.write(request.data(), static_cast<qint64>(request.size()));
    });
    connect(&socket_, &QTcpSocket::readyRead, this, &SourceTableRequest::onReadyRead);
    connect(&socket_, &QTcpSocket::disconnected, this, &SourceTableRequest::onDisconnected);
    connect(&socket_, &QTcpSocket::errorOccurred, this, [this](QAbstractSocket::SocketError e) {
        if (done_ || e == QAbstractSocket::RemoteHostClosedError) return;
        fail(CorrectionSource::describeSocketError(e, hostPort(), displayHost(query_.host),
                                                   socket_.errorString()));
    });
}

SourceTableRequest::~SourceTableRequest() {
    done_ = true;
    socket_.abort();
}

QString SourceTableRequest::hostPort() const {
    return QStringLiteral("%1:%2").arg(displayHost(query_.host)).arg(query_.port);
}

void SourceTableRequest::start() {
    done_ = false;
    timeout_.start(query_.timeoutMs);
    socket_.connectToHost(query_.host, query_.port);
}

void SourceTableRequest::abort() {
    done_ = true;
    timeout_.stop();
    socket_.abort();
}

void SourceTableRequest::fail(const QString &reason) {
    if (done_) return;
    abort();
    emit failed(redactedText(reason, query_.user, query_.password));
}

void SourceTableRequest::finish() {
    if (done_) return;
    table_.finish();
    abort();
    emit received(table_.table());
}

bool SourceTableRequest::acceptHead() {
    const ntrip::ResponseHead &h = reply_.head();
    const QString revision = QString::fromStdString(h.revisionText());
    switch (h.kind) {
    case ntrip::ReplyKind::SourceTable: return true;
    case ntrip::ReplyKind::UnexpectedContent:
        // Some casters label their table text/plain: read it as a table all the same.
        if (h.contentType == "text/plain") return true;
        fail(tr("%1 answered with %2, not a source table: is it an NTRIP caster?")
                     .arg(hostPort(), QString::fromStdString(h.contentType)));
        return false;
    case ntrip::ReplyKind::Unauthorized:
        fail(tr("%1 refused the user name or password for its source table (401 Unauthorized, "
                "%2 reply)")
                     .arg(hostPort(), revision));
        return false;
    case ntrip::ReplyKind::Data:
        fail(tr("%1 sent data instead of its source table (%2 reply)").arg(hostPort(), revision));
        return false;
    case ntrip::ReplyKind::NotNtrip:
        fail(tr("%1 did not answer like an NTRIP caster (it sent \"%2\")")
                     .arg(hostPort(), QString::fromStdString(h.statusLine).left(40)));
        return false;
    default:
        fail(tr("%1 answered \"%2\" instead of its source table (%3 reply)")
                     .arg(hostPort(), QString::fromStdString(h.statusLine), revision));
        return false;
    }
}

void SourceTableRequest::takeBody(std::string_view body) {
    if (body.empty()) return;
    std::string decoded;
    if (reply_.head().chunked) {
        const auto status = chunks_.feed(body, decoded);
        if (status == ntrip::ChunkedDecoder::Status::Error)
            return fail(tr("%1 sent a malformed chunked source table: %2")
                                .arg(hostPort(), QString::fromStdString(chunks_.error())));
        body = decoded;
    }
    bodyBytes_ += body.size();
    table_.feed(body);
    const auto length = reply_.head().contentLength;
    if (table_.complete() || (length && !reply_.head().chunked && bodyBytes_ >= *length) ||
        chunks_.status() == ntrip::ChunkedDecoder::Status::Finished)
        finish();
}

void SourceTableRequest::onReadyRead() {
    if (done_) return;
    const QByteArray bytes = socket_.readAll();
    const std::string_view in(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    if (headAccepted_) return takeBody(in);
    std::string body;
    reply_.feed(in, body);
    if (!reply_.headComplete()) return;
    if (!acceptHead()) return;
    headAccepted_ = true;
    takeBody(body);
}

void SourceTableRequest::onDisconnected() {
    if (done_) return;
    if (!headAccepted_) {
        reply_.finish();
        if (reply_.head().kind == ntrip::ReplyKind::Incomplete)
            return fail(tr("%1 closed the connection without answering").arg(hostPort()));
        if (!acceptHead()) return;
        headAccepted_ = true;
    }
    finish(); // the connection's end ends the table (NTRIP 1 casters may omit its last line)
}

} // namespace gnss::corrections
