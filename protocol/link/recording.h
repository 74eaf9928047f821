#pragma once
// A recording on disk (docs/recording.md):
//   FILE.nmea      exactly the bytes received, nothing added: any NMEA tool reads it as is
//   FILE.nmea.idx  one text line per event: when each chunk of FILE.nmea arrived (host time),
//                  each command sent, each gap in the link
//     R <host ms> <offset> <length>    bytes offset..offset+length of FILE.nmea were received
//     S <host ms> <offset> <sentence>  a command was sent (after `offset` bytes had been received)
//     G <host ms> <offset> <text>      the link was lost or came back (a gap in the data)
//   Host ms = milliseconds since 1970-01-01T00:00:00Z. Lines starting with '#' are comments.
#include <QByteArray>
#include <QString>

#include <atomic>
#include <memory>
#include <vector>

class QFile;

namespace gnss::link {

struct RecordedChunk {
    qint64 hostMs = 0;
    qint64 offset = 0;
    qint64 length = 0;
};

struct RecordedEvent {
    enum class Kind : char { Sent = 'S', Gap = 'G' };
    Kind kind = Kind::Sent;
    qint64 hostMs = 0;
    qint64 offset = 0;
    QString text;
};

struct Recording {
    // FILE.nmea, memory-mapped (not read into memory): `bytes` is a view of `file`'s mapping and
    // lives as long as a copy of `file` does.
    std::shared_ptr<QFile> file;
    QByteArray bytes;
    std::vector<RecordedChunk> chunks; // empty when there is no index
    std::vector<RecordedEvent> events; // sent commands and gaps, in order
    bool hasIndex = false;
};

// The index file next to a recording: "FILE.nmea" → "FILE.nmea.idx".
QString indexPathFor(const QString &nmeaPath);

// Maps FILE and reads FILE.idx when present. Bytes past the last indexed chunk (a recorder that
// died before writing its last index line) become one chunk at the last known time. Returns
// false with `error` set when the file cannot be read or the index contradicts it. Safe to call
// from a worker thread; `cancel` (when given) stops it early (returns false, error empty).
bool loadRecording(const QString &nmeaPath, Recording &out, QString &error,
                   const std::atomic<bool> *cancel = nullptr);

} // namespace gnss::link
