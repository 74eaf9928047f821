#include "link/recorder.h"

#include "link/transport.h"

#include <QDateTime>

namespace gnss::link {

Recorder::Recorder(QObject *parent, Clock clock)
    : QObject(parent),
      clock_(clock ? std::move(clock) : Clock([] { return QDateTime::currentMSecsSinceEpoch(); })) {
}

Recorder::~Recorder() {
    close();
}

bool Recorder::open(const QString &nmeaPath, const QString &source, bool append) {
    close();
    data_.setFileName(nmeaPath);
    index_.setFileName(indexPathFor(nmeaPath));
    const auto mode = QIODevice::WriteOnly | (append ? QIODevice::Append : QIODevice::Truncate);
    if (!data_.open(mode)) {
        error_ = tr("Cannot write %1: %2").arg(nmeaPath, data_.errorString());
        emit errorOccurred(error_);
        return false;
    }
    if (!index_.open(mode)) {
        error_ = tr("Cannot write %1: %2").arg(index_.fileName(), index_.errorString());
        data_.close();
        emit errorOccurred(error_);
        return false;
    }
    offset_ = data_.size();
    if (index_.size() == 0) writeIndex("# gnss-workbench recording index 1 (docs/recording.md)");
    const QString start =
            QDateTime::fromMSecsSinceEpoch(clock_(), Qt::UTC).toString(Qt::ISODateWithMs);
    QString note = QStringLiteral("# started %1").arg(start);
    if (!source.isEmpty()) note += QStringLiteral(" from ") + source;
    writeIndex(note.toUtf8());
    return true;
}

void Recorder::close() {
    detach();
    if (data_.isOpen()) {
        data_.flush();
        data_.close();
    }
    if (index_.isOpen()) {
        index_.flush();
        index_.close();
    }
}

void Recorder::attach(Transport *transport) {
    detach();
    transport_ = transport;
    if (!transport) return;
    connections_ << connect(transport, &Transport::bytesReceived, this, &Recorder::received);
    connections_ << connect(transport, &Transport::bytesSent, this, &Recorder::sent);
    connections_ << connect(transport, &Transport::stateChanged, this, [this](Transport::State s) {
        if (s == Transport::State::Lost && !lostMarked_) {
            lostMarked_ = true;
            gap(tr("link lost: %1").arg(transport_->errorString()));
        } else if (s == Transport::State::Open && lostMarked_) {
            lostMarked_ = false;
            gap(tr("link back: %1").arg(transport_->description()));
        }
    });
}

void Recorder::detach() {
    for (const auto &c : std::as_const(connections_)) disconnect(c);
    connections_.clear();
    transport_ = nullptr;
}

void Recorder::received(const QByteArray &bytes) {
    if (!data_.isOpen() || bytes.isEmpty()) return;
    if (data_.write(bytes) != bytes.size() || !data_.flush()) return writeFailed(data_);
    writeIndex(QByteArray("R ") + QByteArray::number(clock_()) + ' ' + QByteArray::number(offset_) +
               ' ' + QByteArray::number(bytes.size()));
    offset_ += bytes.size();
}

void Recorder::sent(const QByteArray &bytes) {
    if (!index_.isOpen()) return;
    const qint64 now = clock_();
    for (QByteArray line : bytes.split('\n')) {
        line = line.trimmed();
        if (line.isEmpty()) continue;
        writeIndex(QByteArray("S ") + QByteArray::number(now) + ' ' + QByteArray::number(offset_) +
                   ' ' + line);
    }
}

void Recorder::gap(const QString &text) {
    if (!index_.isOpen()) return;
    writeIndex(QByteArray("G ") + QByteArray::number(clock_()) + ' ' + QByteArray::number(offset_) +
               ' ' + text.toUtf8());
}

void Recorder::writeIndex(QByteArray line) {
    // One line whatever a text in it holds (a gap's reason, the source the user typed): a line
    // break would make the rest of it an index line of its own.
    line.replace('\n', ' ').replace('\r', ' ');
    if (index_.write(line + '\n') != line.size() + 1 || !index_.flush()) writeFailed(index_);
}

void Recorder::writeFailed(QFile &f) {
    error_ = tr("Cannot write %1: %2").arg(f.fileName(), f.errorString());
    emit errorOccurred(error_);
}

} // namespace gnss::link
