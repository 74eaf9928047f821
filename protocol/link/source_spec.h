#pragma once
// SourceSpec: where receiver data comes from, as the user named it (the GUI's connection bar,
// its command line and last session, every gnss-cli command): a serial port and its speed
// (0 = detect), a TCP server, a recorded log and how to play it, a built-in simulated receiver.
// A TransportFactory makes the Transport for it.
#include <QString>

namespace gnss::link {

struct SourceSpec {
    enum class Kind { None, Serial, Tcp, Replay, Simulator };
    Kind kind = Kind::None;
    QString name; // port, host:port, file path, or simulated dialect id
    int baud = 0; // serial: 0 = detect; simulator: the host's line speed (0 = the receiver's)
    double speed = 1.0;  // replay and simulator: time factor
    bool asFast = false; // replay: no waiting, everything at once

    bool valid() const { return kind != Kind::None && !name.isEmpty(); }
    QString toString() const; // "serial:/dev/ttyUSB0@115200", "sim:nvs", ... (QSettings)
    static SourceSpec fromString(const QString &s);
    QString displayName() const; // for the user (translated)
};

} // namespace gnss::link
