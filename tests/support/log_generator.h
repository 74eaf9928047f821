#pragma once
// Generates a realistic 10 Hz multi-constellation NMEA 4.11 log (GPS, GLONASS, Galileo, BeiDou;
// RMC, GGA, GSA per system, GSV per system and signal, VTG, ZDA, GST) for benchmarks.
#include <cstddef>
#include <string>

namespace gnss::bench {

// Appends epochs until `out` holds at least `bytes` bytes.
void generateLog(std::string &out, std::size_t bytes);

// The same log a piece at a time: each append() goes on from the epoch the last one ended
// with, so pieces written one after the other are generateLog's log (gnss-loggen writes logs of
// any size so, with a few MB of memory).
class LogGenerator {
public:
    // Appends epochs until `out` holds at least `bytes` bytes.
    void append(std::string &out, std::size_t bytes);

private:
    long epoch_ = 0;
};

// Writes such a log of `bytes` to `path` from a child process (its memory is not the caller's).
bool writeLogFile(const std::string &path, std::size_t bytes);

// A /proc/self/status figure in kB ("RssAnon:": heap and stacks, not mapped files); -1 unknown.
long statusKb(const char *key);

} // namespace gnss::bench
