#pragma once
// TcpCorrectionSource: raw RTCM from a TCP server, e.g. a base receiver's port or a serial
// server in front of a radio. Connects in the background; a drop, a refusal or a stall is
// retried with the backoff.
#include "corrections/raw_correction_source.h"

#include <QTcpSocket>

namespace gnss::corrections {

class TcpCorrectionSource : public RawCorrectionSource {
    Q_OBJECT
public:
    TcpCorrectionSource(QString host, quint16 port, QObject *parent = nullptr);
    ~TcpCorrectionSource() override;

    QString description() const override; // "host:port"

protected:
    void openConnection() override;
    void closeConnection() override;

private:
    QString host_;
    quint16 port_;
    QTcpSocket socket_;
};

} // namespace gnss::corrections
