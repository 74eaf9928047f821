#include "recording.h"

#include <QCoreApplication>
#include <QFile>

namespace gnss::link {

namespace {

QString tr(const char *text) {
    return QCoreApplication::translate("gnss::link::Recording", text);
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
    qint64 expectedOffset = 0, lastMs = 0;
    int lineNo = 0;
    while (!index.atEnd()) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return false;
        const QByteArray raw = index.readLine();
        ++lineNo;
        const QByteArray line = raw.endsWith('\n') ? raw.chopped(1) : raw;
        if (line.isEmpty() || line.startsWith('#')) continue;
        if (!raw.endsWith('\n')) break; // a torn last line: the recorder stopped mid-write
        const QList<QByteArray> parts = line.split(' ');
        bool okMs = false, okOffset = false;
        const qint64 ms = parts.value(1).toLongLong(&okMs);
        const qint64 offset = parts.value(2).toLongLong(&okOffset);
        auto bad = [&](const QString &why) {
            error = tr("%1, line %2: %3").arg(index.fileName()).arg(lineNo).arg(why);
            return false;
        };
        if (parts.size() < 3 || parts[0].size() != 1 || !okMs || !okOffset)
            return bad(tr("not an index line"));
        const char kind = parts[0][0];
        if (kind == 'R') {
            bool okLength = false;
            const qint64 length = parts.value(3).toLongLong(&okLength);
            if (!okLength || length < 0) return bad(tr("bad length"));
            if (offset != expectedOffset)
                return bad(tr("chunk starts at %1, expected %2").arg(offset).arg(expectedOffset));
            if (offset + length > out.bytes.size())
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
