#include "gui/log_player.h"

#include "core/baud_rates.h"
#include "logview/play_schedule.h"

#include <QHostAddress>
#include <QSerialPort>
#include <QTcpServer>
#include <QTcpSocket>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace gnss::app {

namespace {
constexpr int kTickMs = 20;                   // bytes go out in 50 steps a second
constexpr qint64 kMaxSocketBacklog = 1 << 20; // a TCP client this far behind loses bytes
} // namespace

LogPlayer::LogPlayer(QObject *parent) : QObject(parent) {
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &LogPlayer::tick);
}

LogPlayer::~LogPlayer() {
    stop();
}

bool LogPlayer::start(std::shared_ptr<const logview::LogView> view, std::size_t first,
                      std::size_t last, double speed, bool loop, const Target &target,
                      QString *why) {
    stop();
    auto fail = [&](const QString &text) {
        if (why) *why = text;
        stop();
        return false;
    };
    if (!view || view->epochCount() == 0) return fail(tr("no log is open"));
    if (!(speed > 0) || speed > 1000) return fail(tr("the speed must be above 0 and at most 1000"));
    last = std::min(last, view->epochCount() - 1);
    if (first > last) return fail(tr("the range is empty"));
    if (target.kind == Target::Kind::Serial &&
        (target.serialPort.isEmpty() || !isStandardBaud(target.baud)))
        return fail(tr("choose a serial port and a standard baud rate"));
    if (target.kind == Target::Kind::Tcp && target.tcpPort == 0)
        return fail(tr("choose a TCP port from 1 to 65535"));

    switch (target.kind) {
    case Target::Kind::Pty: {
        ptyFd_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (ptyFd_ < 0 || ::grantpt(ptyFd_) != 0 || ::unlockpt(ptyFd_) != 0)
            return fail(tr("cannot make a pseudo-terminal: %1")
                                .arg(QString::fromLocal8Bit(std::strerror(errno))));
        termios t{};
        ::tcgetattr(ptyFd_, &t);
        ::cfmakeraw(&t); // bytes as they are: no echo, no CR/LF translation
        ::tcsetattr(ptyFd_, TCSANOW, &t);
        ptyPath_ = QString::fromLocal8Bit(::ptsname(ptyFd_));
        break;
    }
    case Target::Kind::Tcp:
        server_ = new QTcpServer(this);
        if (!server_->listen(QHostAddress::LocalHost, target.tcpPort))
            return fail(tr("cannot listen on 127.0.0.1:%1: %2")
                                .arg(target.tcpPort)
                                .arg(server_->errorString()));
        connect(server_, &QTcpServer::newConnection, this, &LogPlayer::acceptClients);
        break;
    case Target::Kind::Serial:
        serial_ = new QSerialPort(target.serialPort, this);
        serial_->setBaudRate(target.baud);
        if (!serial_->open(QIODevice::WriteOnly))
            return fail(tr("cannot open %1: %2").arg(target.serialPort, serial_->errorString()));
        break;
    }
    view_ = std::move(view);
    target_ = target;
    loop_ = loop;
    view_->withRecords([&](std::span<const logview::EpochRecord> all) {
        records_.assign(all.begin() + std::ptrdiff_t(first),
                        all.begin() + std::ptrdiff_t(last) + 1);
    });
    due_ = logview::playSchedule(records_, view_->hasHostTimes(), speed);
    end_ = view_->epochEnd(last);
    fromFileStart_ = first == 0; // what precedes the first epoch goes out with it
    next_ = 0;
    sent_ = dropped_ = 0;
    clock_.start();
    timer_.start();
    playing_ = true;
    emit statusChanged();
    return true;
}

void LogPlayer::stop() {
    const bool was = playing_, open = view_ != nullptr;
    playing_ = false;
    timer_.stop();
    view_.reset();
    records_.clear();
    due_.clear();
    // Clients get what was written before they are let go (closing waits for the socket's
    // buffer to empty).
    for (const auto &c : clients_) {
        if (!c) continue;
        connect(c, &QAbstractSocket::disconnected, c, &QObject::deleteLater);
        c->disconnectFromHost();
        if (c->state() == QAbstractSocket::UnconnectedState) c->deleteLater();
    }
    clients_.clear();
    if (server_) server_->deleteLater();
    server_ = nullptr;
    if (serial_) {
        serial_->flush();
        serial_->close();
        serial_->deleteLater();
    }
    serial_ = nullptr;
    if (ptyFd_ >= 0) ::close(ptyFd_);
    ptyFd_ = -1;
    ptyPath_.clear();
    if (open) emit statusChanged();
    if (was) emit finished();
}

void LogPlayer::acceptClients() {
    while (server_ && server_->hasPendingConnections()) {
        QTcpSocket *c = server_->nextPendingConnection();
        c->setParent(this); // outlives the server while it drains
        clients_.emplace_back(c);
    }
    std::erase_if(clients_, [](const QPointer<QTcpSocket> &c) {
        return !c || c->state() != QAbstractSocket::ConnectedState;
    });
    emit statusChanged();
}

bool LogPlayer::begun() const {
    // TCP: the pace starts with the first client (as gnss-cli play's does).
    return target_.kind != Target::Kind::Tcp || !clients_.empty() || next_ > 0;
}

void LogPlayer::writeOut(const char *data, qint64 size) {
    if (size <= 0) return;
    switch (target_.kind) {
    case Target::Kind::Pty: {
        qint64 done = 0;
        while (done < size) {
            const ssize_t n = ::write(ptyFd_, data + done, std::size_t(size - done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break; // nobody reads (EAGAIN: its buffer is full): dropped, counted
            done += n;
        }
        sent_ += quint64(done);
        dropped_ += quint64(size - done);
        break;
    }
    case Target::Kind::Tcp:
        acceptClients();
        for (const auto &c : clients_) {
            if (c->bytesToWrite() > kMaxSocketBacklog) {
                dropped_ += quint64(size);
                continue;
            }
            c->write(data, size);
        }
        sent_ += quint64(size);
        break;
    case Target::Kind::Serial:
        serial_->write(data, size);
        sent_ += quint64(size);
        break;
    }
}

void LogPlayer::tick() {
    if (!playing_) return;
    if (!begun()) {
        clock_.restart();
        return;
    }
    const double now = double(clock_.elapsed()) / 1000.0;
    const std::size_t from = next_;
    while (next_ < records_.size() && due_[next_] <= now) ++next_;
    if (next_ > from) {
        // Epochs [from, next_) in one write: from the first's offset to the next one's.
        const std::uint64_t a = from == 0 && fromFileStart_ ? 0 : records_[from].offset;
        const std::uint64_t b = next_ < records_.size() ? records_[next_].offset : end_;
        const std::string_view bytes = view_->bytes(a, b - a);
        writeOut(bytes.data(), qint64(bytes.size()));
        emit statusChanged();
    }
    if (next_ >= records_.size()) {
        if (loop_) {
            next_ = 0;
            clock_.restart();
        } else {
            // Done: the destination stays open (a pseudo-terminal's reader may still be reading
            // what is in its buffer) until Stop or the next start.
            timer_.stop();
            playing_ = false;
            emit statusChanged();
            emit finished();
        }
    }
}

QString LogPlayer::statusText() const {
    if (!view_) return tr("Not playing");
    QString where;
    switch (target_.kind) {
    case Target::Kind::Pty: where = tr("Pseudo-terminal %1").arg(ptyPath_); break;
    case Target::Kind::Tcp:
        where = clients_.empty()
                        ? tr("127.0.0.1:%1, waiting for a client").arg(target_.tcpPort)
                        : tr("127.0.0.1:%1, clients: %2").arg(target_.tcpPort).arg(clients_.size());
        break;
    case Target::Kind::Serial:
        where = tr("%1 at %2 baud").arg(target_.serialPort).arg(target_.baud);
        break;
    }
    QString text = (playing_ ? tr("%1: epoch %2 of %3, %4 kB sent")
                             : tr("%1: finished, %2 of %3 epochs, %4 kB sent"))
                           .arg(where)
                           .arg(next_)
                           .arg(records_.size())
                           .arg(double(sent_) / 1000, 0, 'f', 1);
    if (dropped_)
        text += tr(", %1 kB dropped (the reader did not keep up)")
                        .arg(double(dropped_) / 1000, 0, 'f', 1);
    return text;
}

} // namespace gnss::app
