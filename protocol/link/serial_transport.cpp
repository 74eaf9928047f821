#include "serial_transport.h"

#include <QFileInfo>

namespace gnss::link {

namespace {

// "/dev/ttyUSB0" and "ttyUSB0" name the same port.
bool samePort(const PortInfo &p, const QString &name) {
    return p.portName == name || p.systemLocation == name ||
           (!name.isEmpty() && QFileInfo(name).canonicalFilePath() == p.systemLocation);
}

} // namespace

SerialTransport::SerialTransport(SerialSettings settings, PortEnumerator enumerate, QObject *parent)
    : Transport(parent), settings_(std::move(settings)),
      enumerate_(enumerate ? std::move(enumerate) : PortEnumerator(systemPorts)) {
    connect(&port_, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = port_.readAll();
        if (!bytes.isEmpty()) emit bytesReceived(bytes);
    });
    connect(&port_, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
}

SerialTransport::~SerialTransport() {
    port_.close();
}

QString SerialTransport::resolvePortName() const {
    if (device_.serialNumber.isEmpty()) return settings_.portName;
    for (const PortInfo &p : enumerate_())
        if (p.sameDevice(device_))
            return p.systemLocation.isEmpty() ? p.portName : p.systemLocation;
    return settings_.portName;
}

bool SerialTransport::open() {
    if (port_.isOpen()) port_.close();
    ++generation_;
    const QString name = resolvePortName();
    port_.setPortName(name);
    port_.setBaudRate(settings_.baud);
    port_.setDataBits(settings_.dataBits);
    port_.setParity(settings_.parity);
    port_.setStopBits(settings_.stopBits);
    port_.setFlowControl(settings_.flowControl);
    if (!port_.open(QIODevice::ReadWrite)) {
        fail(tr("Cannot open %1: %2").arg(name, port_.errorString()), false);
        return false;
    }
    if (name != settings_.portName) settings_.portName = name; // the device moved
    // Remember who is behind the port, to find it again under another name after an unplug.
    for (const PortInfo &p : enumerate_()) {
        if (samePort(p, name)) {
            device_ = p;
            break;
        }
    }
    if (device_.systemLocation.isEmpty()) device_.systemLocation = name;
    setState(State::Open);
    return true;
}

void SerialTransport::close() {
    port_.close();
    setState(State::Closed);
}

bool SerialTransport::writeBytes(const QByteArray &bytes) {
    if (!port_.isOpen()) return false;
    return port_.write(bytes) == bytes.size();
}

QString SerialTransport::description() const {
    return tr("%1 at %2 baud").arg(settings_.portName).arg(settings_.baud);
}

bool SerialTransport::setBaud(int baud) {
    settings_.baud = baud;
    if (!port_.isOpen()) return true;
    return port_.setBaudRate(baud);
}

void SerialTransport::discardInput() {
    if (!port_.isOpen()) return;
    port_.clear(QSerialPort::Input);
    port_.readAll();
}

void SerialTransport::onError(QSerialPort::SerialPortError error) {
    if (error == QSerialPort::NoError) return;
    const bool gone = error == QSerialPort::ResourceError ||
                      error == QSerialPort::PermissionError || error == QSerialPort::ReadError ||
                      error == QSerialPort::WriteError;
    const QString message = tr("%1: %2").arg(settings_.portName, port_.errorString());
    if (!port_.isOpen()) return; // open() reports its own failure
    port_.clearError();
    if (gone) {
        // Close at once: a vanished device's file descriptor keeps signalling otherwise.
        // (Queued: not inside QSerialPort's own notifier; skipped when reopened meanwhile.)
        const int generation = generation_;
        QMetaObject::invokeMethod(
                this,
                [this, generation] {
                    if (generation == generation_) port_.close();
                },
                Qt::QueuedConnection);
    }
    fail(message, gone);
}

} // namespace gnss::link
