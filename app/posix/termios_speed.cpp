#include "posix/termios_speed.h"

#include <utility>

namespace gnss::posix {
namespace {

constexpr std::pair<int, speed_t> kSpeeds[] = {
        {300, B300},       {600, B600},       {1200, B1200},     {2400, B2400},   {4800, B4800},
        {9600, B9600},     {19200, B19200},   {38400, B38400},   {57600, B57600}, {115200, B115200},
        {230400, B230400}, {460800, B460800}, {921600, B921600},
};

} // namespace

std::optional<speed_t> termiosSpeed(int baud) {
    for (const auto &[b, s] : kSpeeds)
        if (b == baud) return s;
    return std::nullopt;
}

int baudOfTermiosSpeed(speed_t speed) {
    for (const auto &[b, s] : kSpeeds)
        if (s == speed) return b;
    return 0;
}

} // namespace gnss::posix
