#pragma once
// GpsdTransport: a receiver that gpsd holds, read through gpsd's TCP socket (by default
// 127.0.0.1:2947). On Linux desktops gpsd often owns the receiver's port (udev rules hand it the
// USB GPS receivers it knows); instead of fighting it for the device, the workbench asks gpsd for
// the receiver's own sentences.
//
// open() connects in the background, as TcpTransport does. The transport stays Connecting while
// gpsd greets it (VERSION), lists its devices (DEVICES) and confirms the watch: it asks
// ?WATCH={"enable":true,"json":false,"raw":1} (with "device":"..." when one was named), so gpsd
// relays the sentences as the receiver sent them and sends none of its own fix reports. Only the
// receiver's sentences reach bytesReceived (GpsdReader strips gpsd's JSON and the hex dumps of
// binary packets). Commands cannot be sent: gpsd owns the port and relays nothing to it, so
// canWrite() is false and readOnlyReason() says so.
#include "link/gpsd_reader.h"
#include "link/transport.h"

#include <QStringList>
#include <QTcpSocket>
#include <QTimer>

namespace gnss::link {

class GpsdTransport : public Transport {
    Q_OBJECT
public:
    static constexpr quint16 kDefaultPort = 2947;

    // Where gpsd listens and which of its devices to watch (empty: every device it has).
    struct Target {
        QString host = QStringLiteral("127.0.0.1");
        quint16 port = kDefaultPort;
        QString device;
    };
    // "HOST[:PORT][/DEVICE]", also with "gpsd://" before it: "localhost", "10.0.0.2:2948",
    // "[::1]:2947/dev/ttyUSB0", ":2948", "/dev/ttyACM0" (gpsd on this machine). False with
    // `error` set when the text is not one.
    static bool parseTarget(const QString &text, Target &out, QString *error = nullptr);
    // The watch request sent after gpsd's greeting.
    static QByteArray watchRequest(const QString &device);

    explicit GpsdTransport(Target target, QObject *parent = nullptr);
    ~GpsdTransport() override;

    bool open() override;
    void close() override;
    // "gpsd at 127.0.0.1:2947" or "gpsd at 127.0.0.1:2947, /dev/ttyUSB0".
    QString description() const override;
    bool canWrite() const override { return false; }
    QString readOnlyReason() const override;

    const Target &target() const { return target_; }
    // What gpsd said about itself and its devices (known once the transport is Open).
    QString gpsdRelease() const { return release_; }
    QStringList gpsdDevices() const { return devices_; }
    // Lines from gpsd that were neither the receiver's sentences nor gpsd's reports.
    quint64 linesDropped() const { return reader_.linesDropped(); }
    // How long the connection and gpsd's greeting may take before it is given up.
    void setConnectTimeout(int ms) { connectTimer_.setInterval(ms); }

protected:
    bool writeBytes(const QByteArray &) override { return false; }

private:
    // Where the conversation with gpsd is: the greeting awaited (from the TCP connect on), the
    // watch sent and its confirmation awaited, the device list asked for after gpsd refused the
    // device watched, sentences flowing.
    enum class Phase { Idle, AwaitVersion, AwaitWatch, AwaitDevices, Streaming };
    void onReadyRead();
    void onReport(const QJsonObject &report);
    void abortSocket();
    // `request`: the device asked for is not gpsd's (see Transport::errorIsRequest()).
    void failOpening(const QString &why, bool request = false);
    void failNoSuchDevice();

    Target target_;
    QTcpSocket socket_;
    QTimer connectTimer_;
    GpsdReader reader_;
    Phase phase_ = Phase::Idle;
    QString release_;
    QStringList devices_;
    bool closing_ = false;
};

} // namespace gnss::link
