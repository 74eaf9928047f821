#pragma once
// SourceSpec: where receiver data comes from, as the user named it (the GUI's connection bar,
// its command line and last session, every gnss-cli command): a serial port and its speed
// (0 = detect), a TCP server, a recorded log and how to play it, a built-in simulated receiver,
// a receiver that gpsd holds (gpsd://HOST[:PORT][/DEVICE]). A TransportFactory makes the
// Transport for it.
#include <QString>

namespace gnss::link {

struct SourceSpec {
    enum class Kind { None, Serial, Tcp, Replay, Simulator, Gpsd };
    Kind kind = Kind::None;
    QString name;       // port, host:port, file path, simulated dialect id, or HOST[:PORT][/DEVICE]
    int baud = 0;       // serial: 0 = detect; simulator: the host's line speed (0 = the receiver's)
    double speed = 1.0; // replay and simulator: time factor
    bool asFast = false; // replay: no waiting, everything at once

    bool valid() const { return kind != Kind::None && !name.isEmpty(); }
    // "serial:/dev/ttyUSB0@115200", "sim:nvs", "gpsd://localhost:2947/dev/ttyUSB0", ... (QSettings)
    QString toString() const;
    static SourceSpec fromString(const QString &s);
    QString displayName() const; // for the user (translated)
    // Where, in a word, beside a receiver's model: the port, host:port, the file's name,
    // "simulated" (translated).
    QString place() const;
};

} // namespace gnss::link
