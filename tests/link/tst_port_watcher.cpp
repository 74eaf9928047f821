// PortWatcher: plugged and unplugged devices are signalled without a restart; a device is
// recognised by its serial number under a new port name.
#include "link/port_watcher.h"

#include <QSignalSpy>
#include <QTest>

using namespace gnss::link;

namespace {

PortInfo usb(const QString &name, const QString &serial) {
    PortInfo p;
    p.portName = name;
    p.systemLocation = "/dev/" + name;
    p.description = "USB-Serial";
    p.manufacturer = "FTDI";
    p.serialNumber = serial;
    p.vendorId = 0x0403;
    p.productId = 0x6001;
    return p;
}

} // namespace

class TstPortWatcher : public QObject {
    Q_OBJECT
private slots:
    void pluggingAndUnpluggingAreSignalled() {
        QList<PortInfo> present{usb("ttyUSB0", "A1")};
        PortWatcher w([&] { return present; });
        QSignalSpy added(&w, &PortWatcher::portAdded), removed(&w, &PortWatcher::portRemoved);
        w.setInterval(20);
        w.start();
        QCOMPARE(added.count(), 1);
        present.append(usb("ttyUSB1", "B2"));
        QTRY_COMPARE(added.count(), 2);
        QCOMPARE(added.last().first().value<PortInfo>().portName, QStringLiteral("ttyUSB1"));
        present.removeFirst();
        QTRY_COMPARE(removed.count(), 1);
        QCOMPARE(removed.first().first().value<PortInfo>().serialNumber, QStringLiteral("A1"));
        QCOMPARE(w.ports().size(), 1);
    }

    void sameSerialNumberIsTheSameDeviceUnderAnotherName() {
        QVERIFY(usb("ttyUSB0", "A1").sameDevice(usb("ttyUSB3", "A1")));
        QVERIFY(!usb("ttyUSB0", "A1").sameDevice(usb("ttyUSB0", "B2")));
        PortInfo plain;
        plain.systemLocation = "/dev/ttyS0";
        PortInfo plain2 = plain;
        QVERIFY(plain.sameDevice(plain2));
        QCOMPARE(usb("ttyUSB0", "A1").usbId(), QStringLiteral("0403:6001"));
        QCOMPARE(plain.usbId(), QString());
    }

    void systemListDoesNotCrash() {
        const auto ports = systemPorts();
        for (const auto &p : ports) QVERIFY(!p.portName.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TstPortWatcher)
#include "tst_port_watcher.moc"
