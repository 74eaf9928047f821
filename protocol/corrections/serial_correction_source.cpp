#include "corrections/serial_correction_source.h"

#include "link/while_closing.h"

namespace gnss::corrections {

SerialCorrectionSource::SerialCorrectionSource(QString portName, int baud, QObject *parent)
    : RawCorrectionSource(parent), portName_(std::move(portName)), baud_(baud) {
    deliverReadsOf(port_);
    connect(&port_, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
        if (!listening() || e == QSerialPort::NoError || e == QSerialPort::TimeoutError) return;
        const QString why = port_.errorString();
        // A device that went away (unplugged) reports ResourceError: opened again later.
        failed(tr("%1: %2").arg(description(), why), true);
    });
}

SerialCorrectionSource::~SerialCorrectionSource() {
    closing_ = true;
    port_.close();
}

QString SerialCorrectionSource::description() const {
    return tr("%1 at %2 baud").arg(portName_).arg(baud_);
}

void SerialCorrectionSource::openConnection() {
    closeConnection();
    setConnecting(tr("Opening %1").arg(description()));
    port_.setPortName(portName_);
    port_.setBaudRate(baud_);
    port_.setDataBits(QSerialPort::Data8);
    port_.setParity(QSerialPort::NoParity);
    port_.setStopBits(QSerialPort::OneStop);
    port_.setFlowControl(QSerialPort::NoFlowControl);
    // Opening a local device does not wait on anything remote: it succeeds or fails at once.
    closing_ = true; // the error signal of a failed open is reported below, once
    const bool ok = port_.open(QIODevice::ReadOnly);
    closing_ = false;
    if (!ok) return failed(tr("Cannot open %1: %2").arg(description(), port_.errorString()), true);
    setReceiving(tr("%1 open, waiting for RTCM").arg(description()));
}

void SerialCorrectionSource::closeConnection() {
    link::whileClosing(closing_, [this] {
        if (port_.isOpen()) port_.close();
        port_.clearError();
    });
}

QString SerialCorrectionSource::stallText(bool) const {
    return tr("No data on %1 for %2 s (is the radio receiving the base?)")
            .arg(description(), QString::number(stallTimeout() / 1000.0));
}

} // namespace gnss::corrections
