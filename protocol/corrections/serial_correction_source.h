#pragma once
// SerialCorrectionSource: RTCM from a radio modem (or any device) on a second serial port,
// beside the receiver's own. The port is opened read-only at the given speed; when it fails or
// vanishes (USB unplugged) it is opened again after the backoff's wait.
#include "corrections/raw_correction_source.h"

#include <QSerialPort>

namespace gnss::corrections {

class SerialCorrectionSource : public RawCorrectionSource {
    Q_OBJECT
public:
    SerialCorrectionSource(QString portName, int baud, QObject *parent = nullptr);
    ~SerialCorrectionSource() override;

    QString description() const override; // "/dev/ttyUSB1 at 38400 baud"

protected:
    void openConnection() override;
    void closeConnection() override;
    QString stallText(bool receiving) const override;

private:
    QString portName_;
    int baud_;
    QSerialPort port_;
};

} // namespace gnss::corrections
