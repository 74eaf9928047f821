// gnss-sim: a simulated GNSS receiver (protocol/sim) behind a pseudo-terminal, a TCP port or
// stdin/stdout. One thread, one poll() loop: read the host's bytes, advance simulated time by
// the elapsed real time x --speed, write what the receiver sent.
//
// On a pseudo-terminal the line speed the other side sets (tcsetattr on the slave, which the
// master sees with tcgetattr) is handed to the receiver: while it differs from the receiver's
// baud the receiver sends garbage and ignores input, as a UART at the wrong speed would.
// SIGHUP power-cycles the simulated receiver (settings come back from its flash).
// The hang-up fault that comes back (hangup=T/DOWN) closes the pseudo-terminal and makes a new
// one; --link keeps a symbolic link to whichever is current (a stable name, as udev gives).
// hangupon=CMD/DOWN does the same the moment the receiver hears CMD (the line goes before its
// answer is written). On TCP both close the client's connection and stop listening (a connection
// attempt is refused, as by a serial-to-Ethernet server that is down); DOWN seconds later the
// same port listens again, its address on a new line of standard output.
// With --rtcm-base the same loop carries an RTCM 3 base station's stream instead.
// --com2 opens a second pseudo-terminal for the receiver's second port (an NV08C-RTK base's RTCM):
// what the receiver sends there is written to it, what a program writes to it is read and
// dropped (the simulated receivers take commands on their first port only).
#include "builtin/dialects.h"
#include "builtin/simulators.h"
#include "posix/termios_speed.h"
#include "sim/sim_args.h"

#include <arpa/inet.h>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <memory>
#include <string>

using namespace gnss;

namespace {

// Poll timeouts: 10 ms while a program has the line (output paced like a UART's), 100 ms while
// nobody does.
constexpr int kActivePollMs = 10;
constexpr int kIdlePollMs = 100;

volatile std::sig_atomic_t g_stop = 0; // the signal that asked to stop
volatile std::sig_atomic_t g_powerCycle = 0;
void onSignal(int signal) {
    g_stop = signal;
}
void onHangupSignal(int) {
    g_powerCycle = 1;
}

double monotonicSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + ts.tv_nsec / 1e9;
}

void setNonBlocking(int fd) {
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
}

// Whether stdin is /dev/null (then "until stdin closes" would end at once: ignore it).
bool stdinIsDevNull() {
    struct stat in {
    }, dn{};
    if (fstat(STDIN_FILENO, &in) != 0 || stat("/dev/null", &dn) != 0) return false;
    return S_ISCHR(in.st_mode) && in.st_rdev == dn.st_rdev;
}

// Writes as much as the peer takes; keeps the rest (bounded: a peer that never reads loses the
// oldest output, as a receiver's full UART buffer would).
void flushTo(int fd, std::string &buffer) {
    while (!buffer.empty()) {
        const ssize_t n = ::write(fd, buffer.data(), buffer.size());
        if (n <= 0) break;
        buffer.erase(0, static_cast<std::size_t>(n));
    }
    if (buffer.size() > 65536) buffer.erase(0, buffer.size() - 65536);
}

// Writes all of `buffer`, waiting for the peer as long as it takes (the end of a --duration run:
// nothing of the log is lost).
void drainTo(int fd, std::string &buffer) {
    while (!buffer.empty()) {
        const ssize_t n = ::write(fd, buffer.data(), buffer.size());
        if (n > 0) {
            buffer.erase(0, static_cast<std::size_t>(n));
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EINTR) break;
        pollfd out{fd, POLLOUT, 0};
        if (::poll(&out, 1, 1000) <= 0 || (out.revents & (POLLERR | POLLHUP))) break;
    }
}

// A pseudo-terminal whose slave is a raw line at `baud` (until the other side sets its own);
// its device path goes on standard output, and to a symbolic link at `link` when one is asked.
// -1 (the reason on standard error) when none could be made.
int openPty(int baud, const std::string &link) {
    const int fd = posix_openpt(O_RDWR | O_NOCTTY);
    if (fd < 0 || grantpt(fd) != 0 || unlockpt(fd) != 0) {
        std::perror("gnss-sim: pseudo-terminal");
        if (fd >= 0) ::close(fd);
        return -1;
    }
    const char *name = ptsname(fd);
    const int slave = ::open(name, O_RDWR | O_NOCTTY);
    if (slave >= 0) {
        termios t{};
        tcgetattr(slave, &t);
        cfmakeraw(&t);
        const speed_t speed = posix::termiosSpeed(baud).value_or(B9600);
        cfsetispeed(&t, speed);
        cfsetospeed(&t, speed);
        tcsetattr(slave, TCSANOW, &t);
        ::close(slave);
    }
    setNonBlocking(fd);
    if (!link.empty()) { // replaced in one step: a program opening it finds the old or the new
        const std::string temporary = link + ".new";
        ::unlink(temporary.c_str());
        if (::symlink(name, temporary.c_str()) != 0 || ::rename(temporary.c_str(), link.c_str()))
            std::perror("gnss-sim: --link");
    }
    std::printf("%s\n", name);
    std::fflush(stdout);
    return fd;
}

// A non-blocking socket listening on 127.0.0.1:`port`, its address on standard output; -1 (the
// reason on standard error) when the port could not be had.
int listenOn(int port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) {
        std::perror("gnss-sim: socket");
        return -1;
    }
    int one = 1; // listening again after a hang-up: the dropped connection is in TIME_WAIT
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::bind(fd, reinterpret_cast<sockaddr *>(&addr), sizeof addr) != 0 || ::listen(fd, 1) != 0) {
        std::fprintf(stderr, "gnss-sim: cannot listen on 127.0.0.1:%d: %s\n", port,
                     std::strerror(errno));
        ::close(fd);
        return -1;
    }
    setNonBlocking(fd);
    std::printf("127.0.0.1:%d\n", port);
    std::fflush(stdout);
    return fd;
}

// Closes a TCP client's connection; what it sent and nobody read is read first, so the close is
// an orderly one (FIN) and not a reset that could take the last bytes sent with it.
void closeClient(int fd) {
    char sink[4096];
    while (::read(fd, sink, sizeof sink) > 0) {
    }
    ::close(fd);
}

} // namespace

int main(int argc, char **argv) {
    const DialectRegistry registry = makeBuiltinRegistry();
    simapp::SimArgs args;
    std::string error;
    const sim::SimulatorTable &simulators = sim::builtinSimulators();
    if (!simapp::parseSimArgs(simulators, argc, argv, args, error)) {
        std::fprintf(stderr, "gnss-sim: %s\nTry 'gnss-sim --help'.\n", error.c_str());
        return 2;
    }
    if (args.help) {
        std::fputs(simapp::usage(registry, simulators).c_str(), stdout);
        return 0;
    }
    if (args.version) {
        std::printf("gnss-sim %s\n", GNSS_VERSION);
        return 0;
    }
    if (args.listDialects) {
        for (std::string_view id : simulators.dialects()) {
            const Dialect *d = registry.find(id);
            std::printf("%.*s\tsim\t%.*s\n", int(id.size()), id.data(),
                        int(d ? d->displayName.size() : id.size()),
                        d ? d->displayName.data() : id.data());
        }
        return 0;
    }
    // Exactly one of the two: a receiver (dialect), or a base station's RTCM stream.
    std::unique_ptr<sim::Receiver> rx;
    std::unique_ptr<sim::RtcmBaseStation> base;
    if (args.rtcmBase)
        base = std::make_unique<sim::RtcmBaseStation>(args.base);
    else
        rx = simulators.make(args.dialect, args.options);
    // A base has no UART of its own: its line runs at --baud, 115200 by default.
    const int deviceBaud = rx ? rx->baud() : (args.options.baud > 0 ? args.options.baud : 115200);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::signal(SIGPIPE, SIG_IGN);
    std::signal(SIGHUP, onHangupSignal); // SIGHUP: simulated power cycle (settings from flash)

    int ioFd = -1;     // where the receiver's bytes go and commands come from
    int listenFd = -1; // TCP only
    const bool isPty = args.transport == simapp::Transport::Pty;
    const bool isTcp = args.transport == simapp::Transport::Tcp;
    if (isPty) {
        ioFd = openPty(deviceBaud, args.link);
        if (ioFd < 0) return 1;
    } else if (isTcp) {
        listenFd = listenOn(args.tcpPort);
        if (listenFd < 0) return 1;
    } else {
        ioFd = STDOUT_FILENO;
    }

    int com2Fd = -1; // --com2: the receiver's second port
    bool com2Idle = true;
    std::string com2Buffer;
    if (args.com2) {
        com2Fd = openPty(deviceBaud, args.com2Link);
        if (com2Fd < 0) return 1;
    }
    bool watchStdin = args.transport == simapp::Transport::Stdout || !stdinIsDevNull();
    std::string outBuffer;
    double last = monotonicSeconds();
    char buf[4096];
    // A pseudo-terminal master reports POLLHUP at once, whatever is asked, while nobody has the
    // slave open: polling it then would spin. While hung up the master is left out of the poll
    // and looked at again every kIdlePollMs (a program opening the device is heard within that).
    bool ptyIdle = false;
    // The hang-up that comes back (hangup=T/DOWN[xCOUNT], on a pseudo-terminal or TCP): the line
    // drops once a program has had it for T simulated seconds; DOWN seconds later it is back.
    const sim::FaultSpec &faults = args.options.faults;
    const bool unplugs =
            rx && (isPty || isTcp) && (faults.hangupRepeats() || !faults.hangupOn.empty());
    bool unplugged = false; // the line is down: back at backAt (simulated time)
    double heldFor = 0, backAt = 0;
    int outages = 0;
    bool heldBefore = false; // a program had the line at the last turn (time since is held time)
    // Unplugged: the program's line is gone, a new one comes `down` simulated seconds later. The
    // name goes first, as a USB device's node does: a program retrying it meets "no such file"
    // until the device is back, never a pseudo-terminal of another program that got the freed
    // number meanwhile. On TCP the listening socket goes first, so a client reconnecting at once
    // is refused rather than taken into the backlog and reset.
    auto unplug = [&](double down) {
        if (!args.link.empty()) ::unlink(args.link.c_str());
        if (isTcp) {
            ::close(listenFd);
            listenFd = -1;
            if (ioFd >= 0) closeClient(ioFd);
        } else {
            ::close(ioFd);
        }
        ioFd = -1;
        unplugged = true;
        backAt = rx->time() + down;
    };
    while (!g_stop) {
        pollfd fds[4];
        int n = 0;
        int stdinIdx = -1, ioIdx = -1, listenIdx = -1, com2Idx = -1;
        if (com2Fd >= 0 && !com2Idle) fds[com2Idx = n++] = {com2Fd, POLLIN, 0};
        if (watchStdin) fds[stdinIdx = n++] = {STDIN_FILENO, POLLIN, 0};
        if (ioFd >= 0 && ioFd != STDOUT_FILENO && !ptyIdle) fds[ioIdx = n++] = {ioFd, POLLIN, 0};
        if (listenFd >= 0) fds[listenIdx = n++] = {listenFd, POLLIN, 0};
        ::poll(fds, static_cast<nfds_t>(n), ptyIdle ? kIdlePollMs : kActivePollMs);
        if (ptyIdle && ioFd >= 0) {
            pollfd probe{ioFd, POLLIN, 0};
            ::poll(&probe, 1, 0);
            ptyIdle = (probe.revents & POLLHUP) != 0;
        }
        if (com2Fd >= 0) { // the second port: is a program on it, and drop what it wrote
            pollfd probe{com2Fd, POLLIN, 0};
            ::poll(&probe, 1, 0);
            com2Idle = (probe.revents & POLLHUP) != 0;
            if (com2Idx >= 0 && (fds[com2Idx].revents & POLLIN))
                while (::read(com2Fd, buf, sizeof buf) > 0) {
                }
        }

        if (stdinIdx >= 0 && (fds[stdinIdx].revents & (POLLIN | POLLHUP))) {
            const ssize_t r = ::read(STDIN_FILENO, buf, sizeof buf);
            if (r <= 0) {
                if (args.duration <= 0) break; // standard input closed: stop
                watchStdin = false;            // --duration ends it; no more commands
                continue;
            }
            if (args.transport == simapp::Transport::Stdout && rx)
                rx->receive(std::string_view(buf, static_cast<std::size_t>(r)));
        }
        bool peerPresent = ioFd >= 0;
        if (listenIdx >= 0 && (fds[listenIdx].revents & POLLIN)) {
            const int c = ::accept(listenFd, nullptr, nullptr);
            if (c >= 0) {
                if (ioFd >= 0) ::close(ioFd);
                ioFd = c;
                setNonBlocking(ioFd);
                outBuffer.clear();
            }
        }
        if (ioIdx >= 0) {
            if (fds[ioIdx].revents & POLLIN) {
                const ssize_t r = ::read(ioFd, buf, sizeof buf);
                if (r > 0 && rx) // a base ignores what clients send (a caster's GGA)
                    rx->receive(std::string_view(buf, static_cast<std::size_t>(r)));
                else if (!isPty && (r == 0 || (r < 0 && errno != EAGAIN))) { // TCP client left
                    ::close(ioFd);
                    ioFd = -1;
                }
            } else if (!isPty && (fds[ioIdx].revents & (POLLHUP | POLLERR))) {
                ::close(ioFd); // TCP client reset
                ioFd = -1;
            }
            // A pseudo-terminal master reports POLLHUP while nobody has the slave open: the
            // receiver keeps running, its output goes nowhere (no stale backlog for the next
            // program that opens the device).
            if (isPty && (fds[ioIdx].revents & POLLHUP)) ptyIdle = true;
        }
        if (ptyIdle) peerPresent = false;
        // hangupon: the receiver heard the command; the line goes before its answer is out.
        if (unplugs && ioFd >= 0 && rx->takeLineDrop()) {
            unplug(faults.hangupOnDown);
            peerPresent = false;
        }
        if (isPty && rx && ioFd >= 0) {
            termios t{};
            if (tcgetattr(ioFd, &t) == 0)
                rx->setLineBaud(posix::baudOfTermiosSpeed(cfgetospeed(&t)));
        }

        if (g_powerCycle) {
            g_powerCycle = 0;
            if (rx) rx->powerCycle();
        }
        const double now = monotonicSeconds();
        double elapsed = (now - last) * args.speed;
        // --duration: the last step ends on it, so the log is the same whatever the host's pace.
        const double simulated = rx ? rx->time() : base->time();
        if (args.duration > 0) elapsed = std::min(elapsed, args.duration - simulated);
        std::string out;
        if (rx) {
            rx->advance(elapsed);
            out = rx->takeOutput();
        } else {
            base->advance(elapsed);
            out = base->takeOutput();
        }
        last = now;
        if (peerPresent && ioFd >= 0) {
            outBuffer += out;
            flushTo(ioFd, outBuffer);
        } else {
            outBuffer.clear();
        }
        if (rx && com2Fd >= 0) {
            com2Buffer += rx->takeOutput(2);
            if (com2Idle)
                com2Buffer.clear();
            else
                flushTo(com2Fd, com2Buffer);
        }
        if (rx && rx->hungUp()) break; // the hang-up fault: drop the line
        if (args.duration > 0 && simulated + elapsed >= args.duration) {
            if (ioFd >= 0 && peerPresent) drainTo(ioFd, outBuffer);
            break;
        }
        if (unplugged && rx->time() >= backAt) { // back, as a new device or listening again
            unplugged = false;
            heldFor = 0;
            if (isTcp) {
                listenFd = listenOn(args.tcpPort);
                if (listenFd < 0) return 1;
            } else {
                ioFd = openPty(rx->baud(), args.link);
                if (ioFd < 0) return 1;
                ptyIdle = true; // until a program opens it
            }
        } else if (unplugs && faults.hangupRepeats() && peerPresent && ioFd >= 0 &&
                   (faults.hangupTimes == 0 || outages < faults.hangupTimes)) {
            if (heldBefore) heldFor += elapsed;
            if (heldFor >= faults.hangupAfter) {
                unplug(faults.hangupDown);
                ++outages;
            }
        }
        heldBefore = peerPresent && ioFd >= 0;
    }
    if (ioFd >= 0 && ioFd != STDOUT_FILENO) ::close(ioFd);
    if (com2Fd >= 0) ::close(com2Fd);
    if (!args.com2Link.empty()) ::unlink(args.com2Link.c_str());
    if (listenFd >= 0) ::close(listenFd);
    if (!args.link.empty()) ::unlink(args.link.c_str());
    // Stopped by SIGINT/SIGTERM: the status a shell gives a program the signal ended (130, 143),
    // as gnss-cli does, so a script can tell it from standard input closing.
    return g_stop ? 128 + g_stop : 0;
}
