#pragma once
// SerialTransport: a receiver on a serial port (QSerialPort). When the port errors or vanishes
// (USB unplug) the transport goes Lost and closes the device; reopening it is the Connection's
// job. A port known by its USB serial number is found again under a new name (ttyUSB0 → ttyUSB1).
#include "link/port_watcher.h"
#include "link/transport.h"

#include <QSerialPort>

namespace gnss::link {

struct SerialSettings {
    QString portName; // "ttyUSB0", "/dev/ttyUSB0", "COM3" or any path to a tty
    int baud = 9600;
    QSerialPort::DataBits dataBits = QSerialPort::Data8;
    QSerialPort::Parity parity = QSerialPort::NoParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
    QSerialPort::FlowControl flowControl = QSerialPort::NoFlowControl;
};

// Where a port name lives in the file system, as QSerialPort opens it: "ttyUSB0" and "pts/3"
// are under /dev, a path ("/dev/ttyUSB0", "./rover", "../rover") stays itself (on systems
// without /dev, the name as given).
QString serialDevicePath(const QString &portName);
// Whether two port names open the same device: "ttyUSB0", "/dev/ttyUSB0" and a
// /dev/serial/by-id/ link to it are one port.
bool sameSerialDevice(const QString &a, const QString &b);

class SerialTransport : public Transport {
    Q_OBJECT
public:
    // `enumerate` lists ports when the device is looked up by serial number (default: the
    // system's).
    explicit SerialTransport(SerialSettings settings, PortEnumerator enumerate = {},
                             QObject *parent = nullptr);
    ~SerialTransport() override;

    bool open() override;
    void close() override;
    QString description() const override;
    qint64 pendingWriteBytes() const override { return port_.bytesToWrite(); }
    int baud() const override { return settings_.baud; }
    bool setBaud(int baud) override;
    void discardInput() override;

    const SerialSettings &settings() const { return settings_; }
    // The device as it was identified at the last successful open (serial number, VID:PID).
    const PortInfo &device() const { return device_; }
    // Where the port is now: same serial number as device(), possibly under a new name.
    // Returns the configured name when the device has no serial number or is not listed.
    QString resolvePortName() const;

protected:
    bool writeBytes(const QByteArray &bytes) override;

private:
    void onError(QSerialPort::SerialPortError error);

    SerialSettings settings_;
    PortEnumerator enumerate_;
    PortInfo device_;
    QSerialPort port_;
    int generation_ = 0;
};

} // namespace gnss::link
