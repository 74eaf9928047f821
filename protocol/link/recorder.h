#pragma once
// Recorder: writes a recording (recording.h, docs/recording.md) as the bytes arrive. Every chunk
// received is written and flushed before the next one is taken, so bytes logged == bytes
// received, also when the program ends or the link drops; a dropped link leaves a gap mark and
// recording carries on into the same files.
#include "link/recording.h"

#include <QFile>
#include <QObject>
#include <QPointer>

#include <functional>

namespace gnss::link {

class Transport;

class Recorder : public QObject {
    Q_OBJECT
public:
    using Clock = std::function<qint64()>; // host time, ms since the Unix epoch
    explicit Recorder(QObject *parent = nullptr, Clock clock = {});
    ~Recorder() override; // flushes and closes

    // Creates (or, with `append`, continues) FILE and FILE.idx. `source` is noted in a comment.
    bool open(const QString &nmeaPath, const QString &source = {}, bool append = false);
    void close();
    bool isOpen() const { return data_.isOpen(); }
    QString errorString() const { return error_; }

    // Records what `transport` receives and sends, and its losses and returns as gaps. One
    // transport at a time; attaching another detaches the first.
    void attach(Transport *transport);
    void detach();

    void received(const QByteArray &bytes);
    void sent(const QByteArray &bytes);
    void gap(const QString &text);

    qint64 bytesRecorded() const { return offset_; }

signals:
    void errorOccurred(const QString &message);

private:
    void writeIndex(QByteArray line); // one line: breaks inside become spaces
    void writeFailed(QFile &f);

    Clock clock_;
    QFile data_, index_;
    qint64 offset_ = 0;
    QString error_;
    QPointer<Transport> transport_;
    QList<QMetaObject::Connection> connections_;
    bool lostMarked_ = false;
};

} // namespace gnss::link
