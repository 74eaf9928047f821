#pragma once
// Test helper for bad input from the user: a file as a user gives it (any bytes, or none at
// all), with a recording index beside it when one is wanted.
#include <QByteArray>
#include <QFile>
#include <QString>
#include <QTemporaryDir>

namespace gnss::test {

// One fix, checksum right: a log that is NMEA, for an index to be wrong about.
inline const QByteArray
        kOneGga("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n");

// Writes `bytes` to `name` in `dir` (no file at all when `bytes` is "-", a file that does not
// exist) and, when `index` is not empty, `index` to its FILE.idx. The file's path; empty when a
// file could not be written.
inline QString writeUserFile(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes,
                             const QByteArray &index = {}) {
    const QString path = dir.filePath(name);
    auto write = [](const QString &to, const QByteArray &b) {
        QFile f(to);
        return f.open(QIODevice::WriteOnly) && f.write(b) == b.size();
    };
    if (bytes != "-" && !write(path, bytes)) return {};
    if (!index.isEmpty() && !write(path + ".idx", index)) return {};
    return path;
}

} // namespace gnss::test
