#pragma once
// What to connect to, as the user chose it (connection bar, command line, last session).
#include <QString>

namespace gnss::app {

struct SourceSpec {
    enum class Kind { None, Serial, Tcp, Replay, Simulator };
    Kind kind = Kind::None;
    QString name; // port, host:port, file path, or simulated dialect id
    int baud = 0; // serial: 0 = detect

    bool valid() const { return kind != Kind::None && !name.isEmpty(); }
    QString toString() const; // "serial:/dev/ttyUSB0@115200", "sim:nvs", ... (QSettings)
    static SourceSpec fromString(const QString &s);
    QString displayName() const; // for the user (translated)
};

} // namespace gnss::app
