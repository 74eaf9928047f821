#pragma once
// NtripSource: RTCM corrections from an NTRIP caster, NTRIP 1 or 2, over QTcpSocket (connected
// in the background; nothing waits).
//
//   connect → request → reply head (ntrip::ResponseHeadParser)
//     data (ICY 200 OK / HTTP 200 gnss/data) → Receiving; body de-chunked when chunked
//     a source table where data was asked → Failed: the mountpoint is not on this caster
//     401 → Failed: wrong user name or password;  404 → Failed: no such mountpoint
//     other codes, refused or dropped connections, stalls → retried with the backoff
//
// The rover's GGA goes up at the start of the data and every ggaIntervalMs while the
// mountpoint wants it (the source table's nmea flag; when unknown, whenever a position is set).
// Credentials go into the Authorization header and nowhere else: no status, error or
// description holds them.
#include "corrections/correction_source.h"
#include "corrections/source_table_request.h"
#include "ntrip/chunked_decoder.h"
#include "ntrip/gga_upload.h"
#include "ntrip/ntrip_request.h"
#include "ntrip/response_head.h"
#include "ntrip/source_table.h"

#include <QDateTime>
#include <QTcpSocket>

#include <optional>

namespace gnss::corrections {

struct NtripSettings {
    QString host;
    quint16 port = 2101;
    QString mountpoint; // without '/'
    QString user;       // empty: no authentication
    QString password;
    ntrip::NtripVersion version = ntrip::NtripVersion::V2;
    enum class Gga { Never, Auto, Always };
    Gga gga = Gga::Auto;       // Auto: unless the source table says the stream does not want it
    int ggaIntervalMs = 10000; // between GGAs while receiving

    // The caster part: where its source table is asked for, with the same credentials.
    SourceTableQuery caster() const;
};

class NtripSource : public CorrectionSource {
    Q_OBJECT
public:
    explicit NtripSource(NtripSettings settings, QObject *parent = nullptr);
    ~NtripSource() override;

    const NtripSettings &settings() const { return settings_; }
    // "host:port/MOUNT" (never the user name or password).
    QString description() const override;

    // The rover's position for the GGA upload: the receiver's fix as it comes, or one typed in.
    void setRoverPosition(const ntrip::GgaPosition &position);
    void clearRoverPosition();
    // What the source table says of this mountpoint's nmea flag (none: not known).
    void setMountpointWantsGga(std::optional<bool> wants) { wantsGga_ = wants; }
    // Whether a GGA would be sent now (a position is set and the mountpoint may want it).
    bool sendsGga() const;
    quint64 ggaCount() const { return ggaCount_; }
    // Where GGA times come from (UTC); tests pin it.
    void setUtcClock(std::function<QDateTime()> clock) { utc_ = std::move(clock); }

    // The caster's last reply head (which NTRIP revision answered, chunked or not ...).
    const ntrip::ResponseHead &lastReply() const { return reply_.head(); }

    // Asks the caster for its source table on a connection of its own (a running stream is
    // not disturbed): sourceTableReceived or sourceTableFailed follows.
    void fetchSourceTable();

signals:
    void sourceTableReceived(const gnss::ntrip::SourceTable &table);
    void sourceTableFailed(const QString &reason);

protected:
    void openConnection() override;
    void closeConnection() override;
    // The password, "user:password" and its Base64 masked as "***".
    QString redacted(const QString &text) const override;

private:
    QString hostPort() const;
    void onConnected();
    void onReadyRead();
    void onDisconnected();
    void onSocketError(QAbstractSocket::SocketError error);
    // The reply's status is known: data goes on, anything else ends this attempt.
    void onReplyKnown();
    void passBody(std::string_view body);
    void sendGga();

    NtripSettings settings_;
    QTcpSocket socket_;
    bool closing_ = false;
    ntrip::ResponseHeadParser reply_;
    ntrip::ChunkedDecoder chunks_;
    bool replyHandled_ = false;
    bool dataStarted_ = false;
    quint64 attemptBytes_ = 0;
    std::optional<ntrip::GgaPosition> position_;
    std::optional<bool> wantsGga_;
    QTimer ggaTimer_;
    quint64 ggaCount_ = 0;
    quint64 ggaAtConnect_ = 0; // ggaCount_ when this connection began
    std::function<QDateTime()> utc_;
    SourceTableRequest *tableRequest_ = nullptr;
};

} // namespace gnss::corrections
