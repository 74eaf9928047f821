#include "corrections/ntrip_source.h"

#include "corrections/source_table_request.h"
#include "link/while_closing.h"

namespace gnss::corrections {

namespace {

std::string_view viewOf(const QByteArray &b) {
    return {b.constData(), static_cast<std::size_t>(b.size())};
}

QString revisionOf(const ntrip::ResponseHead &h) {
    return QString::fromStdString(h.revisionText());
}

} // namespace

SourceTableQuery NtripSettings::caster() const {
    SourceTableQuery q;
    q.host = host;
    q.port = port;
    q.version = version;
    q.user = user;
    q.password = password;
    return q;
}

NtripSource::NtripSource(NtripSettings settings, QObject *parent)
    : CorrectionSource(parent), settings_(std::move(settings)) {
    ggaTimer_.setInterval(std::max(settings_.ggaIntervalMs, 100));
    connect(&ggaTimer_, &QTimer::timeout, this, &NtripSource::sendGga);
    connect(&socket_, &QTcpSocket::connected, this, &NtripSource::onConnected);
    connect(&socket_, &QTcpSocket::readyRead, this, &NtripSource::onReadyRead);
    connect(&socket_, &QTcpSocket::disconnected, this, &NtripSource::onDisconnected);
    connect(&socket_, &QTcpSocket::errorOccurred, this, &NtripSource::onSocketError);
}

NtripSource::~NtripSource() {
    closing_ = true;
    socket_.abort();
}

QString NtripSource::hostPort() const {
    const QString host = displayHost(settings_.host);
    const bool ipv6 = host.contains(QLatin1Char(':'));
    return (ipv6 ? QStringLiteral("[%1]:%2") : QStringLiteral("%1:%2"))
            .arg(host)
            .arg(settings_.port);
}

QString NtripSource::redacted(const QString &text) const {
    return redactedText(text, settings_.user, settings_.password);
}

QString NtripSource::description() const {
    return hostPort() + QLatin1Char('/') + settings_.mountpoint;
}

void NtripSource::setRoverPosition(const ntrip::GgaPosition &position) {
    const bool first = !position_;
    position_ = position;
    // "At the start": when data already flows and no GGA could be sent yet, send one now.
    if (first && dataStarted_ && ggaCount_ == ggaAtConnect_) sendGga();
}

void NtripSource::clearRoverPosition() {
    position_.reset();
}

bool NtripSource::sendsGga() const {
    if (!position_ || settings_.gga == NtripSettings::Gga::Never) return false;
    return settings_.gga == NtripSettings::Gga::Always || wantsGga_.value_or(true);
}

void NtripSource::openConnection() {
    closeConnection();
    reply_ = ntrip::ResponseHeadParser();
    chunks_ = ntrip::ChunkedDecoder();
    replyHandled_ = false;
    dataStarted_ = false;
    attemptBytes_ = 0;
    ggaAtConnect_ = ggaCount_;
    if (settings_.mountpoint.isEmpty())
        return failed(
                tr("No mountpoint given for %1: pick one from its source table").arg(hostPort()),
                false);
    setConnecting(tr("Connecting to %1").arg(hostPort()));
    socket_.connectToHost(settings_.host, settings_.port);
}

void NtripSource::closeConnection() {
    ggaTimer_.stop();
    dataStarted_ = false;
    link::whileClosing(closing_, [this] { socket_.abort(); });
}

void NtripSource::onConnected() {
    if (closing_ || !isActive()) return;
    std::string error;
    const std::string request =
            ntrip::buildRequest(requestTarget(settings_.caster(), settings_.mountpoint), error);
    if (request.empty())
        return failed(
                tr("Cannot ask %1 for data: %2").arg(description(), QString::fromStdString(error)),
                false);
    socket_.write(request.data(), static_cast<qint64>(request.size()));
    setConnecting(tr("Connected to %1, asking for %2 (NTRIP %3)")
                          .arg(hostPort(), settings_.mountpoint)
                          .arg(static_cast<int>(settings_.version)));
}

void NtripSource::onReadyRead() {
    if (closing_) return;
    const QByteArray bytes = socket_.readAll();
    if (bytes.isEmpty() || !isActive()) return;
    attemptBytes_ += static_cast<quint64>(bytes.size());
    if (reply_.headComplete() && replyHandled_) return passBody(viewOf(bytes));
    std::string body;
    reply_.feed(viewOf(bytes), body);
    const ntrip::ReplyKind kind = reply_.head().kind;
    // Data is acted on at once (an NTRIP 1 caster sends nothing after "ICY 200 OK" until the
    // data); any other answer once its head is whole, so its headers can say which revision
    // answered.
    if (!replyHandled_ && kind != ntrip::ReplyKind::Incomplete &&
        (kind == ntrip::ReplyKind::Data || reply_.headComplete()))
        onReplyKnown();
    if (!body.empty()) passBody(body);
}

void NtripSource::onReplyKnown() {
    replyHandled_ = true;
    const ntrip::ResponseHead &h = reply_.head();
    const QString revision = revisionOf(h);
    const QString mount = settings_.mountpoint;
    const QString statusLine = QString::fromStdString(h.statusLine);
    switch (h.kind) {
    case ntrip::ReplyKind::Data: {
        dataStarted_ = true;
        const bool asked2 = settings_.version == ntrip::NtripVersion::V2;
        QString how = revision;
        if (asked2 && h.isNtrip1()) how = tr("asked NTRIP 2, the caster answered %1").arg(revision);
        if (h.chunked) how += tr(", chunked");
        setReceiving(tr("Receiving RTCM from %1 (%2)").arg(description(), how));
        sendGga();
        ggaTimer_.start();
        return;
    }
    case ntrip::ReplyKind::SourceTable:
        return refused(tr("Mountpoint %1 is not on %2: the caster sent its source table instead "
                          "of data (%3 reply)")
                               .arg(mount, hostPort(), revision));
    case ntrip::ReplyKind::Unauthorized:
        return failed(tr("%1 refused the user name or password for mountpoint %2 "
                         "(401 Unauthorized, %3 reply)")
                              .arg(hostPort(), mount, revision),
                      false);
    case ntrip::ReplyKind::NotFound:
        return refused(tr("Mountpoint %1 not found on %2 (404 Not Found, %3 reply)")
                               .arg(mount, hostPort(), revision));
    case ntrip::ReplyKind::OtherStatus:
        return failed(tr("%1 answered \"%2\" for mountpoint %3 (%4 reply)")
                              .arg(hostPort(), statusLine, mount, revision),
                      true);
    case ntrip::ReplyKind::CasterError:
        return failed(tr("%1 answered \"%2\" for mountpoint %3 (%4)")
                              .arg(hostPort(), statusLine, mount, revision),
                      false);
    case ntrip::ReplyKind::UnexpectedContent:
        return failed(tr("%1 answered with %2, not GNSS data: is it an NTRIP caster?")
                              .arg(hostPort(), QString::fromStdString(h.contentType)),
                      false);
    case ntrip::ReplyKind::NotNtrip:
        return failed(tr("%1 did not answer like an NTRIP caster (it sent \"%2\"); a base's raw "
                         "RTCM port needs a TCP source instead")
                              .arg(hostPort(), statusLine.left(40)),
                      false);
    case ntrip::ReplyKind::Incomplete: break;
    }
}

void NtripSource::passBody(std::string_view body) {
    if (!dataStarted_ || body.empty()) return;
    if (!reply_.head().chunked) return deliver(QByteArray(body.data(), qsizetype(body.size())));
    std::string out;
    const auto status = chunks_.feed(body, out);
    if (!out.empty()) deliver(QByteArray::fromStdString(out));
    if (status == ntrip::ChunkedDecoder::Status::Error)
        failed(tr("%1 sent malformed chunked data: %2")
                       .arg(description(), QString::fromStdString(chunks_.error())),
               true);
    else if (status == ntrip::ChunkedDecoder::Status::Finished)
        failed(tr("%1 ended the stream (last chunk)").arg(description()), true);
}

void NtripSource::onDisconnected() {
    if (closing_ || !isActive()) return;
    if (!replyHandled_) {
        reply_.finish(); // a reply cut short: what arrived may still say enough (a bare 401)
        if (reply_.head().kind == ntrip::ReplyKind::Incomplete)
            return failed(tr("%1 closed the connection without answering").arg(hostPort()), true);
        onReplyKnown();
        if (!isActive()) return;
    }
    if (dataStarted_)
        failed(tr("%1 closed the connection mid-stream after %2 bytes")
                       .arg(description())
                       .arg(attemptBytes_),
               true);
}

void NtripSource::onSocketError(QAbstractSocket::SocketError error) {
    if (closing_ || !isActive()) return;
    if (error == QAbstractSocket::RemoteHostClosedError) return; // onDisconnected says it
    failed(describeSocketError(error, hostPort(), displayHost(settings_.host),
                               socket_.errorString()),
           true);
}

void NtripSource::sendGga() {
    if (!dataStarted_ || !sendsGga()) return;
    const QDateTime utc = utc_ ? utc_() : QDateTime::currentDateTimeUtc();
    const std::string gga = ntrip::buildGga(*position_, utc.time().msecsSinceStartOfDay()) + "\r\n";
    socket_.write(gga.data(), static_cast<qint64>(gga.size()));
    ++ggaCount_;
}

void NtripSource::fetchSourceTable() {
    if (tableRequest_) { // the newer request wins: the older one says nothing more
        tableRequest_->abort();
        tableRequest_->deleteLater();
    }
    tableRequest_ = new SourceTableRequest(settings_.caster(), this);
    SourceTableRequest *request = tableRequest_;
    connect(request, &SourceTableRequest::received, this,
            [this, request](const ntrip::SourceTable &table) {
                if (tableRequest_ == request) tableRequest_ = nullptr;
                request->deleteLater();
                emit sourceTableReceived(table);
            });
    connect(request, &SourceTableRequest::failed, this, [this, request](const QString &why) {
        if (tableRequest_ == request) tableRequest_ = nullptr;
        request->deleteLater();
        emit sourceTableFailed(why);
    });
    request->start();
}

} // namespace gnss::corrections
