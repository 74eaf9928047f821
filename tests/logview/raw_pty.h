#pragma once
// A pseudo-terminal opened for reading as a serial program reads it: raw (bytes as they come, no
// line discipline), not the controlling terminal.
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace gnss::test {

// The device at `path` opened read-only and raw, with `flags` besides (O_NONBLOCK); -1 when it
// cannot be opened.
inline int openRawPty(const char *path, int flags = 0) {
    const int fd = ::open(path, O_RDONLY | O_NOCTTY | flags);
    if (fd < 0) return fd;
    termios t{};
    ::tcgetattr(fd, &t);
    ::cfmakeraw(&t);
    ::tcsetattr(fd, TCSANOW, &t);
    return fd;
}

} // namespace gnss::test
