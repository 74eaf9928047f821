#include "sim/standard_output.h"

#include "core/wgs84.h"

#include <cmath>

namespace gnss::sim {

namespace {

constexpr double kKnotsPerMs = 1.0 / 0.514444;

bool fixValid(const SkySnapshot &s) {
    return s.fix != FixKind::None;
}

int systemId(Constellation c) {
    switch (c) {
    case Constellation::Gps:
    case Constellation::Sbas: return 1;
    case Constellation::Glonass: return 2;
    case Constellation::Galileo: return 3;
    case Constellation::BeiDou: return 4;
    case Constellation::Qzss: return 5;
    default: return 1;
    }
}

// Systems grouped as GSA/GSV group them (SBAS travels with GPS).
Constellation group(Constellation c) {
    if (c == Constellation::Sbas) return Constellation::Gps;
    if (c == Constellation::Qzss) return Constellation::Gps;
    return c;
}

constexpr Constellation kGroups[] = {Constellation::Gps, Constellation::Glonass,
                                     Constellation::Galileo, Constellation::BeiDou};

} // namespace

int satelliteId(const SimSatellite &s, Numbering) {
    switch (s.system) {
    case Constellation::Gps: return s.prn;
    case Constellation::Sbas: return s.prn - 87;
    case Constellation::Glonass: return s.prn + 64;
    case Constellation::Galileo: return s.prn;
    case Constellation::BeiDou: return s.prn;
    case Constellation::Qzss: return s.prn;
    default: return s.prn;
    }
}

std::string_view gsvTalker(Constellation c, Numbering) {
    switch (group(c)) {
    case Constellation::Glonass: return "GL";
    case Constellation::Galileo: return "GA";
    case Constellation::BeiDou: return "GB";
    default: return "GP";
    }
}

std::string_view solutionTalker(const SkySnapshot &snap, Numbering n) {
    int systems = 0;
    Constellation last = Constellation::Gps;
    for (Constellation g : kGroups) {
        for (const SimSatellite &s : snap.satellites) {
            if (s.used && group(s.system) == g) {
                ++systems;
                last = g;
                break;
            }
        }
    }
    if (systems > 1) return "GN";
    return gsvTalker(last, n);
}

double speedKnots(const SkySnapshot &snap) {
    return std::hypot(snap.velNorth, snap.velEast) * kKnotsPerMs;
}

double courseDegrees(const SkySnapshot &snap) {
    double c = wgs84::degrees(std::atan2(snap.velEast, snap.velNorth));
    return c < 0 ? c + 360.0 : c;
}

// The position fields GGA and GNS share, set when the fix is valid (left empty otherwise).
template <class Message> void setPosition(Message &m, const SkySnapshot &snap) {
    if (!fixValid(snap)) return;
    m.lat = snap.lat;
    m.lon = snap.lon;
    m.hdop = snap.dops.hdop;
    m.altMsl = snap.altMsl;
    m.geoidSep = snap.geoidSep;
}

nmea::Gga ggaOf(const SkySnapshot &snap, const EpochTime &t, int timeDecimals) {
    nmea::Gga m;
    m.time = nmea::timeOfDay(t.utcSecondOfDay, timeDecimals);
    m.quality = ggaQuality(snap.fix);
    m.satsUsed = snap.used;
    setPosition(m, snap);
    return m;
}

std::string ggaSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st) {
    const auto talker = st.gpTalkerForGgaRmc ? "GP" : solutionTalker(snap, st.numbering);
    return nmea::encodeGga(talker, ggaOf(snap, t, st.format.timeDecimals), st.format);
}

nmea::Rmc rmcOf(const SkySnapshot &snap, const EpochTime &t, int timeDecimals) {
    nmea::Rmc m;
    m.time = nmea::timeOfDay(t.utcSecondOfDay, timeDecimals);
    m.status = fixValid(snap) ? 'A' : 'V';
    if (fixValid(snap)) {
        m.lat = snap.lat;
        m.lon = snap.lon;
        m.sogKnots = speedKnots(snap);
        m.cog = courseDegrees(snap);
    }
    m.date = t.date;
    m.mode = modeIndicator(snap.fix);
    return m;
}

std::string rmcSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st) {
    nmea::Rmc m = rmcOf(snap, t, st.format.timeDecimals);
    if (st.numbering == Numbering::Nmea41) m.navStatus = fixValid(snap) ? 'S' : 'V';
    const auto talker = st.gpTalkerForGgaRmc ? "GP" : solutionTalker(snap, st.numbering);
    return nmea::encodeRmc(talker, m, st.format);
}

std::string vtgSentence(const SkySnapshot &snap, const StandardStyle &st) {
    nmea::Vtg m;
    if (fixValid(snap)) {
        m.cogTrue = courseDegrees(snap);
        m.sogKnots = speedKnots(snap);
        m.sogKmh = *m.sogKnots * 1.852;
    }
    m.mode = modeIndicator(snap.fix);
    return nmea::encodeVtg(solutionTalker(snap, st.numbering), m);
}

std::string zdaSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st) {
    nmea::Zda m;
    m.time = nmea::timeOfDay(t.utcSecondOfDay, st.format.timeDecimals);
    m.date = t.date;
    m.tzHours = 0;
    m.tzMinutes = 0;
    return nmea::encodeZda(solutionTalker(snap, st.numbering), m, st.format);
}

std::string gllSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st) {
    nmea::Gll m;
    if (fixValid(snap)) {
        m.lat = snap.lat;
        m.lon = snap.lon;
    }
    m.time = nmea::timeOfDay(t.utcSecondOfDay, st.format.timeDecimals);
    m.status = fixValid(snap) ? 'A' : 'V';
    m.mode = modeIndicator(snap.fix);
    return nmea::encodeGll(solutionTalker(snap, st.numbering), m, st.format);
}

std::string gnsSentence(const SkySnapshot &snap, const EpochTime &t, const StandardStyle &st) {
    nmea::Gns m;
    m.time = nmea::timeOfDay(t.utcSecondOfDay, st.format.timeDecimals);
    // One mode character per system: GPS, GLONASS, Galileo, BeiDou.
    std::string mode;
    for (Constellation g : kGroups) {
        bool used = false;
        for (const SimSatellite &s : snap.satellites)
            used = used || (s.used && group(s.system) == g);
        mode.push_back(used ? modeIndicator(snap.fix) : 'N');
    }
    m.mode = mode;
    m.satsUsed = snap.used;
    setPosition(m, snap);
    if (st.numbering == Numbering::Nmea41) m.navStatus = fixValid(snap) ? 'S' : 'V';
    return nmea::encodeGns(solutionTalker(snap, st.numbering), m, st.format);
}

std::string hdtSentence(std::optional<double> heading, const StandardStyle &) {
    nmea::Hdt m;
    m.heading = heading;
    return nmea::encodeHdt("GP", m);
}

std::vector<std::string> gsaSentences(const SkySnapshot &snap, const StandardStyle &st) {
    std::vector<std::string> out;
    const auto talker = solutionTalker(snap, st.numbering);
    const bool multi = talker == "GN";
    auto make = [&](std::optional<Constellation> only) {
        nmea::Gsa m;
        m.mode = 'A';
        m.fix = fixValid(snap) ? 3 : 1;
        for (const SimSatellite &s : snap.satellites) {
            if (!s.used || (only && group(s.system) != *only)) continue;
            if (m.idCount == 12) break; // 12 id fields per GSA
            m.ids[m.idCount++] = satelliteId(s, st.numbering);
        }
        if (fixValid(snap)) {
            m.pdop = snap.dops.pdop;
            m.hdop = snap.dops.hdop;
            m.vdop = snap.dops.vdop;
        }
        if (st.numbering == Numbering::Nmea41)
            m.systemId = systemId(only ? *only : Constellation::Gps);
        out.push_back(nmea::encodeGsa(talker, m));
    };
    if (!multi) {
        Constellation only = Constellation::Gps;
        for (const SimSatellite &s : snap.satellites)
            if (s.used) {
                only = group(s.system);
                break;
            }
        make(fixValid(snap) ? std::optional<Constellation>(only) : std::nullopt);
        return out;
    }
    for (Constellation g : kGroups) {
        bool any = false;
        for (const SimSatellite &s : snap.satellites) any = any || (s.used && group(s.system) == g);
        if (any) make(g);
    }
    return out;
}

std::vector<std::string> gsvSentences(const SkySnapshot &snap, const StandardStyle &st) {
    std::vector<std::string> out;
    for (std::string_view talker : {"GP", "GL", "GA", "GB"}) {
        std::vector<nmea::GsvSatellite> list;
        for (const SimSatellite &s : snap.satellites) {
            if (gsvTalker(s.system, st.numbering) != talker) continue;
            nmea::GsvSatellite g;
            g.id = satelliteId(s, st.numbering);
            g.elevation = static_cast<int>(std::lround(s.elevation));
            g.azimuth = static_cast<int>(std::lround(s.azimuth)) % 360;
            if (s.tracked) g.snr = static_cast<int>(std::lround(s.snr));
            list.push_back(g);
        }
        if (list.empty()) continue;
        const std::optional<int> signal =
                st.numbering == Numbering::Nmea41 ? std::optional<int>(1) : std::nullopt;
        for (std::string &s : nmea::encodeGsvGroup(talker, list, signal))
            out.push_back(std::move(s));
    }
    return out;
}

} // namespace gnss::sim
