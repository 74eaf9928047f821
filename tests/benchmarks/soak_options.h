#pragma once
// gnss-soak's command line.
#include <QString>
#include <QStringList>

namespace gnss::soak {

struct SoakOptions {
    double hours = 24;        // --hours: simulated hours
    double everyMinutes = 60; // --every: simulated minutes between samples
    double warmUpHours = 1;   // --warm-up: growth is measured from here (capped to hours / 4)
    double limitMb = 5;       // --limit: allowed growth of RSS and heap after the warm-up
    QString cli;              // --cli monitor|record: gnss-cli instead of the window
    QString bin;              // --bin DIR: where gnss-cli and gnss-sim are (default: beside)
    double speed = 1000;      // --speed: gnss-sim's speed for --cli
    int rateHz = 10;          // --rate: the NVS simulator's PVT rate for --cli (1, 2, 5, 10)
    QString sky = "sim";      // --sky sim|soak: for --cli, gnss-sim or the soak's 20 Hz sky
};

} // namespace gnss::soak
