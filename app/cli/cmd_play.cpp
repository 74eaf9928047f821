// gnss-cli play: a log played out at its own pace (or X times faster) to a pseudo-terminal, TCP
// clients on 127.0.0.1 or a serial port, like gpsd's gpsfake but timed by the log: the host
// times of a recording's index when it has them, else the epochs' UTC times. The bytes sent are
// exactly the file's.
#include "cli/log_open.h"
#include "link/serial_transport.h"
#include "logview/play_schedule.h"
#include "posix/termios_speed.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

namespace gnss::cli {
namespace {

// Where the bytes go.
class Output {
public:
    ~Output() {
        for (int c : clients_) ::close(c);
        if (listen_ >= 0) ::close(listen_);
        if (fd_ >= 0) ::close(fd_);
    }

    bool openPty() {
        fd_ = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (fd_ < 0 || ::grantpt(fd_) != 0 || ::unlockpt(fd_) != 0) return fail("pseudo-terminal");
        termios t{};
        ::tcgetattr(fd_, &t);
        ::cfmakeraw(&t); // bytes as they are: no echo, no CR/LF translation
        ::tcsetattr(fd_, TCSANOW, &t);
        std::printf("%s\n", ::ptsname(fd_));
        std::fflush(stdout);
        pty_ = true;
        return true;
    }

    bool openSerial(const std::string &port, int baud) {
        const std::string path = link::serialDevicePath(QString::fromStdString(port)).toStdString();
        fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY);
        if (fd_ < 0) return fail(path);
        termios t{};
        if (::tcgetattr(fd_, &t) != 0) return fail(path + " (not a terminal)");
        ::cfmakeraw(&t);
        const auto speed = posix::termiosSpeed(baud);
        if (!speed) {
            error_ = "unsupported baud " + std::to_string(baud);
            return false;
        }
        ::cfsetspeed(&t, *speed);
        ::tcsetattr(fd_, TCSANOW, &t);
        return true;
    }

    bool listenTcp(int port) {
        listen_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        const int one = 1;
        ::setsockopt(listen_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(static_cast<std::uint16_t>(port));
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        if (::bind(listen_, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0 ||
            ::listen(listen_, 8) != 0)
            return fail("127.0.0.1:" + std::to_string(port));
        std::fprintf(stderr, "gnss-cli: listening on 127.0.0.1:%d\n", port);
        return true;
    }

    // TCP: waits for the first client (the pace starts with it). False when interrupted.
    bool waitForClient(const volatile std::sig_atomic_t &stop) {
        while (listen_ >= 0 && clients_.empty()) {
            if (stop) return false;
            acceptClients(100);
        }
        return true;
    }

    // Writes to every destination; false when nobody can take bytes any more.
    bool write(std::string_view bytes) {
        if (listen_ >= 0) {
            acceptClients(0);
            for (auto it = clients_.begin(); it != clients_.end();) {
                if (!writeAll(*it, bytes, true)) {
                    std::fprintf(stderr, "gnss-cli: a client left\n");
                    ::close(*it);
                    it = clients_.erase(it);
                } else {
                    ++it;
                }
            }
            return true;
        }
        if (!writeAll(fd_, bytes, false)) return false;
        return true;
    }

    // A pseudo-terminal whose reader has come and gone.
    bool readerGone() const {
        if (!pty_) return false;
        pollfd p{fd_, POLLOUT, 0};
        return ::poll(&p, 1, 0) > 0 && (p.revents & POLLHUP);
    }
    // Waits until what was written has left: a serial line drained; a pseudo-terminal's reader
    // done with it (it closes its side), at most `ms`, since closing ours would cut it short.
    void drain(int ms) {
        if (fd_ >= 0 && !pty_) ::tcdrain(fd_);
        for (int waited = 0; pty_ && waited < ms && !readerGone(); waited += 20)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const std::string &error() const { return error_; }

private:
    bool fail(const std::string &what) {
        error_ = what + ": " + std::strerror(errno);
        return false;
    }
    void acceptClients(int timeoutMs) {
        pollfd p{listen_, POLLIN, 0};
        while (::poll(&p, 1, timeoutMs) > 0 && (p.revents & POLLIN)) {
            const int c = ::accept4(listen_, nullptr, nullptr, SOCK_CLOEXEC);
            if (c < 0) break;
            clients_.push_back(c);
            std::fprintf(stderr, "gnss-cli: a client connected\n");
            timeoutMs = 0;
        }
    }
    static bool writeAll(int fd, std::string_view b, bool socket) {
        while (!b.empty()) {
            const ssize_t n = socket ? ::send(fd, b.data(), b.size(), MSG_NOSIGNAL)
                                     : ::write(fd, b.data(), b.size());
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            b.remove_prefix(static_cast<std::size_t>(n));
        }
        return true;
    }

    int fd_ = -1, listen_ = -1;
    bool pty_ = false;
    std::vector<int> clients_;
    std::string error_;
};

volatile std::sig_atomic_t g_stop = 0;
void onSignal(int s) {
    g_stop = s;
}

} // namespace

int cmdPlay(const CliContext &ctx) {
    const Args &args = ctx.args;
    const int kinds =
            args.flag("pty") + args.option("tcp").has_value() + args.option("port").has_value();
    if (kinds != 1) {
        if (kinds == 0)
            std::fprintf(stderr, "gnss-cli: play needs one of --pty, --tcp PORT, --port P\n");
        else
            std::fprintf(stderr,
                         "gnss-cli: play takes one of --pty, --tcp PORT, --port P, not %d of "
                         "them\n",
                         kinds);
        return 2;
    }
    double speed = 1;
    if (const auto s = args.option("speed")) {
        char *end = nullptr;
        speed = std::strtod(s->c_str(), &end);
        if (!end || *end || !(speed > 0)) {
            std::fprintf(stderr, "gnss-cli: --speed takes a number > 0, not '%s'\n", s->c_str());
            return 2;
        }
    }
    int tcpPort = 0, baud = 9600;
    if (const auto p = args.option("tcp")) {
        tcpPort = std::atoi(p->c_str());
        if (tcpPort <= 0 || tcpPort > 65535) {
            std::fprintf(stderr, "gnss-cli: --tcp takes a port number, not '%s'\n", p->c_str());
            return 2;
        }
    }
    if (const auto b = args.option("baud")) baud = std::atoi(b->c_str());
    OpenedLog log;
    if (const int rc = openLogForCommand(ctx, log)) return rc;
    if (log.empty()) {
        std::fprintf(stderr, "gnss-cli: nothing to play\n");
        return 1;
    }
    Output out;
    const bool opened = args.flag("pty") ? out.openPty()
                        : tcpPort > 0    ? out.listenTcp(tcpPort)
                                         : out.openSerial(*args.option("port"), baud);
    if (!opened) {
        std::fprintf(stderr, "gnss-cli: %s\n", out.error().c_str());
        return 1;
    }
    g_stop = 0;
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGPIPE, SIG_IGN);
    if (!out.waitForClient(g_stop)) return 128 + g_stop;

    std::vector<logview::EpochRecord> recs;
    log.view->withRecords([&](std::span<const logview::EpochRecord> all) {
        recs.assign(all.begin() + static_cast<std::ptrdiff_t>(log.first),
                    all.begin() + static_cast<std::ptrdiff_t>(log.last) + 1);
    });
    const std::vector<double> due = logview::playSchedule(recs, log.view->hasHostTimes(), speed);
    const std::uint64_t end = log.view->epochEnd(log.last);
    const bool loop = args.flag("loop");
    do {
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < recs.size(); ++i) {
            std::this_thread::sleep_until(start + std::chrono::duration<double>(due[i]));
            if (g_stop) return 128 + g_stop;
            const std::uint64_t from = i == 0 && log.first == 0 ? 0 : recs[i].offset;
            const std::uint64_t to = i + 1 < recs.size() ? recs[i + 1].offset : end;
            if (!out.write(log.view->bytes(from, to - from))) {
                std::fprintf(stderr, "gnss-cli: the reader went away\n");
                return 0;
            }
            if (out.readerGone()) return 0;
        }
    } while (loop && !g_stop);
    out.drain(3000);
    return g_stop ? 128 + g_stop : 0;
}

} // namespace gnss::cli
