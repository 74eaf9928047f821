#include "link/recording.h"

#include <QCoreApplication>
#include <QFile>

#include <charconv>

namespace gnss::link {

namespace {

// The context lupdate files these texts under (a free tr() in namespace gnss::link): under
// "gnss::link::Recording" they were never found, and the errors stayed in English.
QString tr(const char *text) {
    return QCoreApplication::translate("gnss::link", text);
}

// A whole field of decimal digits, '-' allowed in front, nothing else: no sign '+', no spaces,
// no bytes after a NUL (QByteArray::toLongLong takes all three, so "5\0junk" read as 5), the
// same rule as the log viewer's reader (logview/host_times.cpp).
bool decimal(const QByteArray &field, qint64 &out) {
    const char *end = field.constData() + field.size();
    const auto r = std::from_chars(field.constData(), end, out);
    return r.ec == std::errc() && r.ptr == end && !field.isEmpty();
}

} // namespace

QString indexPathFor(const QString &nmeaPath) {
    return nmeaPath + QStringLiteral(".idx");
}

bool loadRecording(const QString &nmeaPath, Recording &out, QString &error,
                   const std::atomic<bool> *cancel) {
    out = {};
    auto data = std::make_shared<QFile>(nmeaPath);
    if (!data->open(QIODevice::ReadOnly)) {
        error = tr("Cannot read %1: %2").arg(nmeaPath, data->errorString());
        return false;
    }
    if (data->size() > 0) {
        uchar *map = data->map(0, data->size());
        if (!map) {
            error = tr("Cannot map %1: %2").arg(nmeaPath, data->errorString());
            return false;
        }
        out.bytes = QByteArray::fromRawData(reinterpret_cast<const char *>(map),
                                            static_cast<qsizetype>(data->size()));
    }
    out.file = std::move(data);
    QFile index(indexPathFor(nmeaPath));
    if (!index.exists()) return true;
    if (!index.open(QIODevice::ReadOnly)) {
        error = tr("Cannot read %1: %2").arg(index.fileName(), index.errorString());
        return false;
    }
    out.hasIndex = true;
    qint64 expectedOffset = 0, lastMs = 0, lastOffset = 0;
    int lineNo = 0;
    while (!index.atEnd()) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return false;
        const QByteArray raw = index.readLine();
        ++lineNo;
        QByteArray line = raw.endsWith('\n') ? raw.chopped(1) : raw;
        if (line.endsWith('\r')) line.chop(1); // CR LF (an index copied through Windows)
        if (line.isEmpty() || line.startsWith('#')) continue;
        if (!raw.endsWith('\n')) break; // a torn last line: the recorder stopped mid-write
        const QList<QByteArray> parts = line.split(' ');
        qint64 ms = 0, offset = 0;
        auto bad = [&](const QString &why) {
            error = tr("%1, line %2: %3").arg(index.fileName()).arg(lineNo).arg(why);
            return false;
        };
        if (parts.size() < 3 || parts[0].size() != 1 || !decimal(parts[1], ms) ||
            !decimal(parts[2], offset) || offset < 0)
            return bad(tr("not an index line"));
        // A host time before 1970 is no clock reading; refusing it also keeps every difference
        // of two host times (the replay's and the viewer's pace) from overflowing.
        if (ms < 0) return bad(tr("bad host time"));
        // Records are written as the bytes arrive: their offsets never go back, nor past the data.
        if (offset < lastOffset)
            return bad(
                    tr("offset %1 is before the previous record's %2").arg(offset).arg(lastOffset));
        if (offset > out.bytes.size()) return bad(tr("offset past the end of the data file"));
        lastOffset = offset;
        const char kind = parts[0][0];
        if (kind == 'R') {
            qint64 length = 0;
            if (parts.size() < 4 || !decimal(parts[3], length) || length < 0)
                return bad(tr("bad length"));
            if (offset != expectedOffset)
                return bad(tr("chunk starts at %1, expected %2").arg(offset).arg(expectedOffset));
            if (length > out.bytes.size() - offset) // offset <= size here: no overflow
                return bad(tr("chunk ends past the end of the data file"));
            out.chunks.push_back({ms, offset, length});
            expectedOffset = offset + length;
        } else if (kind == 'S' || kind == 'G') {
            const int textStart = parts[0].size() + parts[1].size() + parts[2].size() + 3;
            out.events.push_back({static_cast<RecordedEvent::Kind>(kind), ms, offset,
                                  QString::fromUtf8(line.mid(textStart))});
        } else {
            return bad(tr("unknown record '%1'").arg(QLatin1Char(kind)));
        }
        lastMs = ms;
    }
    if (expectedOffset < out.bytes.size())
        out.chunks.push_back({lastMs, expectedOffset, out.bytes.size() - expectedOffset});
    return true;
}

} // namespace gnss::link
