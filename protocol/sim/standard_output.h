#pragma once
// Standard sentences (GGA, RMC, GSA, GSV, VTG, ZDA, GLL, GNS, HDT) of one epoch of the sky model,
// in the numbering and talker conventions a receiver uses. Built with nmea/nmea_encoders.h.
#include "nmea/nmea_encoders.h"
#include "sim/sky_model.h"

#include <string>
#include <vector>

namespace gnss::sim {

enum class Numbering : std::uint8_t {
    Nmea40, // GP GPS 1-32 + SBAS 33-64, GL GLONASS 65-96, GA Galileo 1-36; no system ids
    Nmea41, // as 4.0 plus GB BeiDou 1-63, GSA system id and GSV signal id
};
// (A family's own numbering, other than these, is written by its simulated receiver in its own
// folder.)

struct StandardStyle {
    nmea::EncodeFormat format;
    Numbering numbering = Numbering::Nmea41;
    bool gpTalkerForGgaRmc = false; // NVS "compatibility mode": GGA/RMC always GP
};

struct EpochTime {
    double utcSecondOfDay = 0;
    Date date;
};

int satelliteId(const SimSatellite &s, Numbering n);
std::string_view gsvTalker(Constellation c, Numbering n);
// "GN" when the solution uses several systems, else that system's talker (GP when none).
std::string_view solutionTalker(const SkySnapshot &snap, Numbering n);

nmea::Gga ggaOf(const SkySnapshot &snap, const EpochTime &t, int timeDecimals);
// RMC's time, status, position, speed, course, date and mode (the navigational status, which
// only NMEA 4.1 has, is left to the caller).
nmea::Rmc rmcOf(const SkySnapshot &snap, const EpochTime &t, int timeDecimals);
std::string ggaSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st);
std::string rmcSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st);
std::string vtgSentence(const SkySnapshot &snap, const StandardStyle &st);
std::string zdaSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st);
std::string gllSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st);
std::string gnsSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st);
std::string hdtSentence(std::optional<double> heading, const StandardStyle &st);
// One GSA per system in use when several are (GN), one otherwise.
std::vector<std::string> gsaSentences(const SkySnapshot &snap, const StandardStyle &st);
// GSV groups per talker, in the order GP, GL, GA, GB.
std::vector<std::string> gsvSentences(const SkySnapshot &snap, const StandardStyle &st);

// Speed over ground (knots) and course (degrees) of the snapshot's velocity.
double speedKnots(const SkySnapshot &snap);
double courseDegrees(const SkySnapshot &snap);

} // namespace gnss::sim
