#pragma once
// Serial line speeds as POSIX termios names them (B9600, ...): one table for gnss-cli play's
// serial output and gnss-sim's pseudo-terminal.
#include <termios.h>

#include <optional>

namespace gnss::posix {

// B9600 for 9600; nothing for a speed termios has no name for.
std::optional<speed_t> termiosSpeed(int baud);
// 9600 for B9600; 0 for a code not in the table.
int baudOfTermiosSpeed(speed_t speed);

} // namespace gnss::posix
