#pragma once
// LogPlayer: plays a log (or a range of it) out to other software, as gpsd's gpsfake does but
// timed by the log: to a new pseudo-terminal, to TCP clients on 127.0.0.1, or to a serial port,
// at the log's pace times a speed factor, optionally looping. The bytes sent are exactly the
// file's; the pace is the one `gnss-cli play` uses (logview::playSchedule). Runs on the GUI
// thread's event loop with non-blocking writes: a reader that does not keep up loses bytes (and
// they are counted), never the window.
#include "logview/log_view.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <memory>

class QSerialPort;
class QTcpServer;
class QTcpSocket;

namespace gnss::app {

class LogPlayer : public QObject {
    Q_OBJECT
public:
    struct Target {
        enum class Kind { Pty, Tcp, Serial } kind = Kind::Pty;
        quint16 tcpPort = 10110; // NMEA over TCP's usual port
        QString serialPort;
        int baud = 9600;
    };

    explicit LogPlayer(QObject *parent = nullptr);
    ~LogPlayer() override;

    // Starts playing epochs [first, last] of `view`; false (and `why`) when the destination
    // cannot be opened or the request is malformed (nothing is sent then).
    bool start(std::shared_ptr<const logview::LogView> view, std::size_t first, std::size_t last,
               double speed, bool loop, const Target &target, QString *why);
    void stop();
    // Playing (a finished play keeps its destination open until stop() or the next start()).
    bool running() const { return playing_; }

    // The pseudo-terminal's device (for the reader), while playing to one.
    QString ptyPath() const { return ptyPath_; }
    quint64 bytesSent() const { return sent_; }
    quint64 bytesDropped() const { return dropped_; }
    std::size_t epochsSent() const { return next_; }
    // "Pseudo-terminal /dev/pts/4: epoch 120 of 600, 48 kB sent".
    QString statusText() const;

signals:
    void statusChanged();
    void finished();

private:
    void tick();
    void writeOut(const char *data, qint64 size);
    void acceptClients();
    bool begun() const;

    std::shared_ptr<const logview::LogView> view_;
    std::vector<logview::EpochRecord> records_;
    std::vector<double> due_;
    std::uint64_t end_ = 0;
    bool fromFileStart_ = false, loop_ = false;
    Target target_;
    QTimer timer_;
    QElapsedTimer clock_;
    std::size_t next_ = 0;
    bool playing_ = false;
    quint64 sent_ = 0, dropped_ = 0;
    int ptyFd_ = -1;
    QString ptyPath_;
    QTcpServer *server_ = nullptr;
    std::vector<QPointer<QTcpSocket>> clients_;
    QSerialPort *serial_ = nullptr;
};

} // namespace gnss::app
