#pragma once
// gnss-sim's command line, parsed apart from main() so it stays small and readable.
#include "core/dialect_registry.h"
#include "sim/rtcm_base_station.h"
#include "sim/simulator_table.h"

#include <string>

namespace gnss::simapp {

enum class Transport { Pty, Tcp, Stdout };

struct SimArgs {
    std::string dialect;
    Transport transport = Transport::Pty;
    int tcpPort = 0;
    std::string link;     // --link PATH: a symbolic link to the pseudo-terminal in use
    bool com2 = false;    // --com2: a second pseudo-terminal for the receiver's port 2
    std::string com2Link; // --com2-link PATH
    double speed = 1.0;
    double duration = 0; // --duration S: end after S simulated seconds (0: run on)
    sim::SimOptions options;
    // --rtcm-base: an RTCM 3 base station's stream instead of a receiver (no --dialect).
    bool rtcmBase = false;
    sim::BaseStationConfig base;
    bool help = false;         // --help, -h: print kUsage
    bool version = false;      // --version
    bool listDialects = false; // --list-dialects: "ID\tsim\tNAME" per simulated receiver
};

// The --help text; the receivers it offers are the table's, described by their records.
std::string usage(const DialectRegistry &registry, const sim::SimulatorTable &simulators);

// Returns false with `error` set on a bad command line; true with `help` or `version` set when
// either was asked, whatever else is on the line. --dialect takes the table's ones.
bool parseSimArgs(const sim::SimulatorTable &simulators, int argc, char **argv, SimArgs &out,
                  std::string &error);

} // namespace gnss::simapp
