#include "link/port_watcher.h"

#include <QSerialPortInfo>

namespace gnss::link {

// How often the list of serial ports is read again (a receiver plugged in shows within it).
constexpr int kPortScanMs = 1000;

QString PortInfo::usbId() const {
    if (vendorId < 0 || productId < 0) return {};
    return QStringLiteral("%1:%2")
            .arg(vendorId, 4, 16, QLatin1Char('0'))
            .arg(productId, 4, 16, QLatin1Char('0'));
}

bool PortInfo::sameDevice(const PortInfo &other) const {
    if (!serialNumber.isEmpty() || !other.serialNumber.isEmpty())
        return serialNumber == other.serialNumber && vendorId == other.vendorId &&
               productId == other.productId;
    return systemLocation == other.systemLocation;
}

QList<PortInfo> systemPorts() {
    QList<PortInfo> out;
    for (const QSerialPortInfo &i : QSerialPortInfo::availablePorts()) {
        PortInfo p;
        p.portName = i.portName();
        p.systemLocation = i.systemLocation();
        p.description = i.description();
        p.manufacturer = i.manufacturer();
        p.serialNumber = i.serialNumber();
        if (i.hasVendorIdentifier()) p.vendorId = i.vendorIdentifier();
        if (i.hasProductIdentifier()) p.productId = i.productIdentifier();
        out.append(p);
    }
    return out;
}

PortWatcher::PortWatcher(PortEnumerator enumerate, QObject *parent)
    : QObject(parent), enumerate_(enumerate ? std::move(enumerate) : PortEnumerator(systemPorts)) {
    timer_.setInterval(kPortScanMs);
    connect(&timer_, &QTimer::timeout, this, &PortWatcher::refresh);
}

void PortWatcher::start() {
    refresh();
    timer_.start();
}

void PortWatcher::refresh() {
    const QList<PortInfo> now = enumerate_();
    bool changed = false;
    for (const PortInfo &old : std::as_const(ports_)) {
        if (!now.contains(old)) {
            changed = true;
            emit portRemoved(old);
        }
    }
    for (const PortInfo &p : now) {
        if (!ports_.contains(p)) {
            changed = true;
            emit portAdded(p);
        }
    }
    ports_ = now;
    if (changed) emit portsChanged();
}

} // namespace gnss::link
