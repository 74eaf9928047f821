#include "link/gpsd_reader.h"

#include <QJsonDocument>

namespace gnss::link {

QByteArray GpsdReader::feed(const QByteArray &bytes, std::vector<QJsonObject> &reports) {
    QByteArray out;
    qsizetype from = 0;
    while (from < bytes.size()) {
        const qsizetype nl = bytes.indexOf('\n', from);
        if (nl < 0) {
            if (!skipping_) partial_ += bytes.mid(from);
            if (partial_.size() > kMaxLine) { // no line end in sight: not gpsd's output
                partial_.clear();
                skipping_ = true;
                ++dropped_;
            }
            break;
        }
        QByteArray line = partial_ + bytes.mid(from, nl - from);
        partial_.clear();
        from = nl + 1;
        if (skipping_) { // the end of a line already counted as dropped
            skipping_ = false;
            continue;
        }
        while (line.endsWith('\r')) line.chop(1);
        if (line.isEmpty()) continue;
        const char first = line.front();
        if (first == '$' || first == '!') {
            out += line;
            out += "\r\n";
        } else if (first == '{') {
            const QJsonDocument doc = QJsonDocument::fromJson(line);
            if (doc.isObject())
                reports.push_back(doc.object());
            else
                ++dropped_;
        } else {
            ++dropped_;
        }
    }
    return out;
}

} // namespace gnss::link
