#pragma once
// PortWatcher: the serial ports present, with what identifies the device behind each (USB
// description, manufacturer, serial number, VID:PID), refreshed every second. Qt has no hot-plug
// signal on Linux, so polling is what makes a newly plugged receiver appear without a restart.
#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>

namespace gnss::link {

struct PortInfo {
    QString portName;       // "ttyUSB0"
    QString systemLocation; // "/dev/ttyUSB0"
    QString description;
    QString manufacturer;
    QString serialNumber;
    int vendorId = -1; // USB VID, -1 when not a USB device
    int productId = -1;

    // "1546:01a8", empty when not USB.
    QString usbId() const;
    // Two entries describe the same device: same serial number (even under another port name),
    // or, when there is none, the same location.
    bool sameDevice(const PortInfo &other) const;
    bool operator==(const PortInfo &o) const = default;
};

using PortEnumerator = std::function<QList<PortInfo>()>;

// The ports QSerialPortInfo lists now.
QList<PortInfo> systemPorts();

class PortWatcher : public QObject {
    Q_OBJECT
public:
    // `enumerate` defaults to systemPorts(); tests inject a fake list.
    explicit PortWatcher(PortEnumerator enumerate = {}, QObject *parent = nullptr);

    QList<PortInfo> ports() const { return ports_; }
    void setInterval(int ms) { timer_.setInterval(ms); }
    void start();
    void stop() { timer_.stop(); }

public slots:
    // Reads the list now and signals the differences.
    void refresh();

signals:
    void portAdded(const gnss::link::PortInfo &port);
    void portRemoved(const gnss::link::PortInfo &port);
    void portsChanged();

private:
    PortEnumerator enumerate_;
    QList<PortInfo> ports_;
    QTimer timer_;
};

} // namespace gnss::link
