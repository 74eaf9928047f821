#include "geostar_sim_receiver.h"

#include "core/sentence_builder.h"
#include "geostar/geostar_dialect.h"
#include "geostar/geostar_messages.h"
#include "nmea/nmea_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnss::sim {

namespace {

constexpr double kAlmanacAfter = 30.0; // seconds of tracking until the almanacs are complete
constexpr double kSbasAfter = 20.0;    // seconds after the first fix until SBAS corrections
constexpr int kPositionDecimals = 6;   // GeoS-5 rev. 1.1: ddmm.mmmmmm

// The code a message gets when switched on: the spec's NQUERY example shows GGA/GSA at the
// output rate and GSV/ZDA/DTM once a second; the other messages follow the same split.
char onCode(std::string_view name) {
    return (name == "GSV" || name == "ZDA" || name == "DTM" || name == "RLM") ? '1' : 'R';
}

int rateCode(int hz) {
    switch (hz) {
    case 10: return 0;
    case 5: return 1;
    case 2: return 2;
    default: return 3;
    }
}

int outputIndex(std::string_view name) {
    for (std::size_t i = 0; i < GeoStarReceiver::kOutputs.size(); ++i)
        if (!name.empty() && GeoStarReceiver::kOutputs[i] == name) return static_cast<int>(i);
    return -1;
}

Constellation groupOf(Constellation c) {
    return c == Constellation::Sbas ? Constellation::Gps : c;
}

// Satellite id: v2.x 1-32 GPS, 33-64 SBAS, 65-88 GLONASS, 101-136 Galileo; v4.10 Galileo 1-36.
int idOf(const SimSatellite &s, int version) {
    switch (s.system) {
    case Constellation::Sbas: return s.prn - 87;
    case Constellation::Glonass: return s.prn + 64;
    case Constellation::Galileo: return version == 2 ? s.prn + 100 : s.prn;
    default: return s.prn;
    }
}

std::string pad(int v, int width) {
    char b[16];
    std::snprintf(b, sizeof b, "%0*d", width, v);
    return b;
}

std::string dop(double v) {
    return formatFixed(std::min(v, 99.9), 1);
}

char modeOf(FixKind k) {
    return modeIndicator(k);
}

} // namespace

GeoStarReceiver::GeoStarReceiver(const SimOptions &options)
    : Receiver(geostar::dialect(), options) {
    current_ = flash_ = defaults();
    if (options.baud > 0) current_.baud = flash_.baud = options.baud;
    almanacSince_ = kAlmanacAfter;
}

GeoStarReceiver::Settings GeoStarReceiver::defaults() {
    Settings s;
    s.codes.fill('0');
    // NQUERY example of 3.12: $GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0
    s.codes[outputIndex("GGA")] = 'R';
    s.codes[outputIndex("GSA")] = 'R';
    s.codes[outputIndex("GSV")] = '1';
    s.codes[outputIndex("ZDA")] = '1';
    s.codes[outputIndex("DTM")] = '1';
    return s;
}

bool GeoStarReceiver::allStandardOff() const {
    for (std::size_t i = 0; i < kOutputs.size(); ++i)
        if (!kOutputs[i].empty() && kOutputs[i] != "RLM" && current_.codes[i] != '0') return false;
    return true;
}

UseMask GeoStarReceiver::useMask() const {
    UseMask m;
    m.gps = current_.gnss != "GLN";
    m.glonass = current_.gnss != "GPS";
    m.galileo = current_.gnss == "MIX";
    m.beidou = false;
    m.beidouHardware = false; // GeoS-5: GPS, GLONASS, Galileo, QZSS, SBAS
    m.sbas = m.gps;
    m.elevationMask = current_.elevationMask;
    return m;
}

FixKind GeoStarReceiver::fixAfter(double seconds) const {
    const FixKind base = Receiver::fixAfter(seconds);
    if (base == FixKind::None) return base;
    // SBAS corrections (GeoS-5M) once the SBAS message has been received, GPS in use.
    if (current_.gnss != "GLN" && seconds - ttff() >= kSbasAfter) return FixKind::Differential;
    return base;
}

void GeoStarReceiver::onReset(ResetKind kind) {
    almanacValid_ = almanacValid_ || time() >= almanacSince_; // collected before the reset
    if (kind == ResetKind::PowerCycle) {
        current_ = flash_;
        loadedFromFlash_ = flashWritten_;
        setBaudNow(current_.baud);
        binary_ = false;
        announce_ = true;
        almanacValid_ = almanacInFlash_;
    }
    if (kind == ResetKind::Cold) almanacValid_ = false;
    hotStart_ = kind == ResetKind::Hot;
    validSinceStart_ = false;
    almanacSince_ = time() + (almanacValid_ ? 0.0 : kAlmanacAfter);
    epochIndex_ = 0;
}

// ---- Commands -----------------------------------------------------------------------------

void GeoStarReceiver::onCommand(const Sentence &s, const Message *decoded, std::string_view) {
    if (binary_ || !decoded) return;
    const auto *c = message_cast<geostar::Command>(*decoded);
    if (!c || !c->def) return;
    const geostar::CommandDef &d = *c->def;
    if (d.text == "RQUERY") {
        reply(s, rqueryReply());
    } else if (d.text == "NQUERY") {
        reply(s, nqueryReply());
    } else if (d.text == "SAVEFL") {
        flash_ = current_;
        flashWritten_ = true;
        almanacInFlash_ = almanacValid_ || time() >= almanacSince_;
        flashWriteUntil_ = time() + 1.0;
    } else if (d.text == "SWPROT") {
        binary_ = true;
    } else if (d.text == "CSTART") {
        reset(ResetKind::Cold);
    } else if (d.text == "WSTART") {
        reset(ResetKind::Warm);
    } else if (d.text == "HSTART") {
        reset(ResetKind::Hot);
    } else if (d.settingKey == "port.BDR") {
        current_.baud = std::atoi(std::string(d.value).c_str());
        reply(s, std::string(), current_.baud); // no answer; the port switches at once
    } else {
        apply(d.settingKey, d.value);
    }
}

void GeoStarReceiver::apply(std::string_view key, std::string_view value) {
    const int n = std::atoi(std::string(value).c_str());
    if (key.substr(0, 7) == "output." && outputIndex(key.substr(7)) >= 0) {
        const std::string_view name = key.substr(7);
        current_.codes[outputIndex(name)] = n ? onCode(name) : '0';
    } else if (key == "output.NMEAV") {
        current_.nmeaVersion = n;
    } else if (key == "output.RATE") {
        current_.rateHz = n;
        rescheduleEpochs();
    } else if (key == "power.PSM") {
        current_.powerSaving = n != 0;
    } else if (key == "nav.ELEV") {
        current_.elevationMask = n;
    } else if (key == "nav.DAT") {
        current_.datum = std::string(value);
    } else if (key == "nav.NVS") {
        current_.gnss = std::string(value);
    } else if (key == "port.STOP") {
        current_.stopBits = n;
    }
}

// ---- Status words -------------------------------------------------------------------------

std::uint32_t GeoStarReceiver::statusWord() const {
    const SkySnapshot &snap = lastSnapshot();
    const bool fix = currentFix() != FixKind::None;
    const bool tracking =
            snap.used > 0 || std::any_of(snap.satellites.begin(), snap.satellites.end(),
                                         [](const SimSatellite &x) { return x.tracked; });
    const bool almanac = almanacValid_ || time() >= almanacSince_;
    const UseMask m = useMask();
    std::uint32_t w = 0;
    auto bit = [&](int b, bool on) {
        if (on) w |= 1u << b;
    };
    bit(30, time() < flashWriteUntil_);
    bit(24, currentFix() == FixKind::Differential);
    bit(23, true); // ACTIVE (sleep is not simulated)
    bit(22, currentFix() == FixKind::Differential);
    bit(19, fix);
    bit(18, validSinceStart_);
    bit(15, hotStart_);
    bit(14, tracking && sinceTracking() >= ttff() + 12.5); // iono/UTC from page 18
    bit(13, tracking && sinceTracking() >= ttff());
    bit(12, tracking && sinceTracking() >= ttff());
    bit(10, almanac && m.galileo);
    bit(9, almanac && m.glonass);
    bit(8, almanac && m.gps);
    w |= 3u << 6; // antenna: normal
    bit(5, true); // GLONASS AGC
    bit(4, true); // GPS AGC
    bit(3, loadedFromFlash_);
    bit(2, true); // PLL
    bit(1, true); // RTC
    bit(0, true); // backup RAM
    return w;
}

std::uint32_t GeoStarReceiver::configRegister1() const {
    const UseMask m = useMask();
    std::uint32_t w = 0;
    auto bit = [&](int b, bool on) {
        if (on) w |= 1u << b;
    };
    bit(30, true);                 // antenna power
    bit(24, current_.powerSaving); // power saving modes allowed (RELAXED FIX, bit 25 = 0)
    w |= 1u << 21;                 // dynamics: pedestrian/car
    w |= static_cast<std::uint32_t>(rateCode(current_.rateHz)) << 18;
    bit(15, true); // Kalman filter
    bit(14, true); // 2D first fix allowed
    bit(7, true);  // 1PPS on, GPS time scale, positive
    bit(4, true);  // SBAS
    bit(2, m.galileo);
    bit(1, m.gps);
    bit(0, m.glonass);
    return w;
}

std::uint32_t GeoStarReceiver::configRegister2() const {
    std::uint32_t w = 0xF7FFu << 16; // GeoS-5M
    if (current_.datum == "P90") w |= 1u << 14;
    w |= 1u << 8; // differential allowed
    w |= 1u << 3; // all satellites used, with or without corrections
    w |= 1u << 2; // SBAS PRN automatic
    return w;
}

std::string GeoStarReceiver::rqueryReply() const {
    char b[96];
    std::snprintf(b, sizeof b, "GPSGG,RQUERY,GEOS-5,V.5.102,100518,%08X,%08X,%08X", statusWord(),
                  configRegister1(), configRegister2());
    return buildSentence(b);
}

std::string GeoStarReceiver::nqueryReply() const {
    std::string b = "GPSGG,NQUERY,1," + std::to_string(rateCode(current_.rateHz)) + "," +
                    std::to_string(current_.nmeaVersion);
    for (char c : current_.codes) {
        b += ',';
        b += c;
    }
    return buildSentence(b);
}

// ---- Output -------------------------------------------------------------------------------

void GeoStarReceiver::onEpoch(const SkySnapshot &snap) {
    if (snap.fix != FixKind::None) validSinceStart_ = true;
    if (binary_) return;
    const double t = time();
    if (announce_) { // once after power-on (3.11, 3.12)
        send(rqueryReply());
        send(nqueryReply());
        announce_ = false;
        lastAllOffReport_ = t;
    }
    for (std::string_view name : kOutputs) {
        if (name.empty()) continue;
        const char code = current_.codes[outputIndex(name)];
        const double sec = std::round(t);
        const bool wholeSecond = std::fabs(t - sec) < 1e-6;
        const long s = static_cast<long>(sec);
        bool due = false;
        switch (code) {
        case 'R': due = true; break;
        case '1': due = wholeSecond; break;
        case '2': due = wholeSecond && s % 2 == 0; break;
        case '3': due = wholeSecond && s % 20 == 0; break;
        default: break;
        }
        if (name == "RLM") due = due && wholeSecond && s % 60 == 30; // a test message a minute
        if (due)
            for (const std::string &line : sentencesOf(name, snap)) send(line);
    }
    // Every standard message off: RQUERY and NQUERY once a second instead (3.11, 3.12).
    if (allStandardOff() && t - lastAllOffReport_ >= 1.0 - 1e-6) {
        send(rqueryReply());
        send(nqueryReply());
        lastAllOffReport_ = t;
    }
    ++epochIndex_;
}

std::string GeoStarReceiver::talker() const {
    if (current_.nmeaVersion == 2) return "GP";
    if (current_.gnss == "GPS") return "GP";
    if (current_.gnss == "GLN") return "GL";
    return "GN";
}

std::vector<std::string> GeoStarReceiver::sentencesOf(std::string_view name,
                                                      const SkySnapshot &snap) const {
    const EpochTime t{utcSecondOfDay(), utcDate()};
    const bool valid = snap.fix != FixKind::None;
    nmea::EncodeFormat f;
    f.positionDecimals = kPositionDecimals;
    if (name == "GGA") {
        std::vector<std::string> out{gga(snap)};
        if (current_.nmeaVersion == 4)
            for (std::string &s : gns(snap)) out.push_back(std::move(s));
        return out;
    }
    if (name == "GSA") return gsa(snap);
    if (name == "GSV") return gsv(snap);
    if (name == "DTM") return {dtm()};
    if (name == "RLM") return {rlm()};
    if (name == "GLL") {
        nmea::Gll m;
        if (valid) {
            m.lat = snap.lat;
            m.lon = snap.lon;
        }
        m.time = nmea::timeOfDay(t.utcSecondOfDay, 2);
        m.status = valid ? 'A' : 'V';
        m.mode = modeOf(snap.fix);
        return {nmea::encodeGll(talker(), m, f)};
    }
    if (name == "RMC") {
        nmea::Rmc m;
        m.time = nmea::timeOfDay(t.utcSecondOfDay, 2);
        m.status = valid ? 'A' : 'V';
        if (valid) {
            m.lat = snap.lat;
            m.lon = snap.lon;
            m.sogKnots = speedKnots(snap);
            m.cog = courseDegrees(snap);
        }
        m.date = t.date;
        m.mode = modeOf(snap.fix);
        if (current_.nmeaVersion == 4) m.navStatus = 'V'; // "not formed by the receiver"
        return {nmea::encodeRmc(talker(), m, f)};
    }
    if (name == "VTG") {
        nmea::Vtg m;
        if (valid) {
            m.cogTrue = courseDegrees(snap);
            m.sogKnots = speedKnots(snap);
            m.sogKmh = *m.sogKnots * 1.852;
        }
        m.mode = modeOf(snap.fix);
        return {nmea::encodeVtg(talker(), m)};
    }
    if (name == "ZDA") {
        nmea::Zda m;
        m.time = nmea::timeOfDay(t.utcSecondOfDay, 2);
        m.date = t.date;
        m.tzHours = 0;
        m.tzMinutes = 0;
        return {nmea::encodeZda(talker(), m, f)};
    }
    return {};
}

std::string GeoStarReceiver::gga(const SkySnapshot &snap) const {
    const EpochTime t{utcSecondOfDay(), utcDate()};
    nmea::Gga m = ggaOf(snap, t, 2);
    if (snap.fix == FixKind::Differential) {
        // SBAS: the station field carries the SBAS satellite's PRN (revision 1.1).
        for (const SimSatellite &s : snap.satellites)
            if (s.system == Constellation::Sbas && s.tracked) {
                m.dgpsStation = s.prn;
                m.dgpsAge = 1.0;
                break;
            }
    }
    nmea::EncodeFormat f;
    f.positionDecimals = kPositionDecimals;
    return nmea::encodeGga("GP", m, f); // GGA: GP only (3.1)
}

std::vector<std::string> GeoStarReceiver::gns(const SkySnapshot &snap) const {
    // v4.10: one main sentence (GN in a mixed mode) and, in a mixed mode, one subsidiary
    // sentence per system with its satellite count in the mode position (3.3).
    const EpochTime t{utcSecondOfDay(), utcDate()};
    const bool valid = snap.fix != FixKind::None;
    const UseMask m = useMask();
    const std::pair<Constellation, std::string_view> systems[] = {{Constellation::Gps, "GP"},
                                                                  {Constellation::Glonass, "GL"},
                                                                  {Constellation::Galileo, "GA"}};
    std::string mode;
    int counts[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        for (const SimSatellite &s : snap.satellites)
            if (s.used && groupOf(s.system) == systems[i].first) ++counts[i];
        mode.push_back(valid && counts[i] > 0 ? modeOf(snap.fix) : 'N');
    }
    mode.push_back('N'); // QZSS
    nmea::Gns g;
    g.time = nmea::timeOfDay(t.utcSecondOfDay, 2);
    g.mode = mode;
    g.satsUsed = snap.used;
    if (valid) {
        g.lat = snap.lat;
        g.lon = snap.lon;
        g.hdop = snap.dops.hdop;
        g.altMsl = snap.altMsl;
        g.geoidSep = snap.geoidSep;
    }
    g.navStatus = 'V';
    nmea::EncodeFormat f;
    f.positionDecimals = kPositionDecimals;
    std::vector<std::string> out{nmea::encodeGns(talker(), g, f)};
    if (current_.gnss != "MIX") return out;
    const bool enabled[3] = {m.gps, m.glonass, m.galileo};
    for (int i = 0; i < 3; ++i) {
        if (!enabled[i]) continue;
        out.push_back(buildSentence(std::string(systems[i].second) + "GNS," +
                                    nmea::formatTime(*g.time, 2) + ",,,,," + pad(counts[i], 2) +
                                    ",,,,,,,"));
    }
    return out;
}

std::vector<std::string> GeoStarReceiver::gsa(const SkySnapshot &snap) const {
    const bool valid = snap.fix != FixKind::None;
    const UseMask m = useMask();
    const int v = current_.nmeaVersion;
    struct Group {
        Constellation system;
        std::string_view talker;
        int systemId;
        bool enabled;
    };
    const Group groups[] = {{Constellation::Gps, "GP", 1, m.gps},
                            {Constellation::Glonass, "GL", 2, m.glonass},
                            {Constellation::Galileo, "GA", 3, m.galileo}};
    std::vector<std::string> out;
    for (const Group &g : groups) {
        if (!g.enabled) continue;
        std::string b = std::string(v == 2 ? g.talker : talker()) + "GSA,A," + (valid ? "3" : "1");
        int n = 0;
        for (const SimSatellite &s : snap.satellites) {
            if (!s.used || groupOf(s.system) != g.system || n == 12) continue;
            b += "," + pad(idOf(s, v), v == 2 ? 3 : 2);
            ++n;
        }
        for (; n < 12; ++n) b += ',';
        // No solution: 9.9 in every DOP field (3.4 examples).
        const Dops d = valid ? snap.dops : Dops{9.9, 9.9, 9.9, 9.9, 9.9, 9.9, 9.9};
        b += "," + dop(d.pdop) + "," + dop(d.hdop) + "," + dop(d.vdop);
        if (v == 4) b += "," + std::to_string(g.systemId);
        out.push_back(buildSentence(b));
    }
    return out;
}

std::vector<std::string> GeoStarReceiver::gsv(const SkySnapshot &snap) const {
    const int v = current_.nmeaVersion;
    const UseMask m = useMask();
    struct Group {
        std::string_view talker;
        std::vector<const SimSatellite *> sats;
        int signal;
    };
    std::vector<Group> groups;
    auto visible = [&](const SimSatellite &s) {
        if (s.system == Constellation::BeiDou) return false;
        return m.enabled(s.system) || (s.system == Constellation::Sbas && m.gps);
    };
    if (v == 2) { // v2.x: everything under GP, ordered by id
        Group g{"GP", {}, 0};
        for (const SimSatellite &s : snap.satellites)
            if (visible(s)) g.sats.push_back(&s);
        std::sort(g.sats.begin(), g.sats.end(), [](const SimSatellite *a, const SimSatellite *b) {
            return idOf(*a, 2) < idOf(*b, 2);
        });
        groups.push_back(std::move(g));
    } else {
        const std::pair<Constellation, Group> per[] = {{Constellation::Gps, {"GP", {}, 1}},
                                                       {Constellation::Glonass, {"GL", {}, 1}},
                                                       {Constellation::Galileo, {"GA", {}, 7}}};
        for (const auto &[system, proto] : per) {
            Group g = proto;
            for (const SimSatellite &s : snap.satellites)
                if (visible(s) && groupOf(s.system) == system) g.sats.push_back(&s);
            if (!g.sats.empty()) groups.push_back(std::move(g));
        }
    }
    std::vector<std::string> out;
    for (const Group &g : groups) {
        const int total = static_cast<int>(g.sats.size());
        const int count = std::max(1, (total + 3) / 4);
        for (int i = 0; i < count; ++i) {
            std::string b = std::string(g.talker) + "GSV,";
            b += v == 2 ? pad(count, 2) + "," + pad(i + 1, 2) + "," + pad(total, 2)
                        : std::to_string(count) + "," + std::to_string(i + 1) + "," + pad(total, 2);
            for (int k = i * 4; k < std::min(total, i * 4 + 4); ++k) {
                const SimSatellite &s = *g.sats[k];
                b += "," + pad(idOf(s, v), v == 2 ? 3 : 2) + "," +
                     pad(static_cast<int>(std::lround(s.elevation)), 2) + "," +
                     pad(static_cast<int>(std::lround(s.azimuth)) % 360, 3) + ",";
                if (s.tracked) b += pad(static_cast<int>(std::lround(s.snr)), 2);
            }
            if (v == 4) b += "," + std::to_string(g.signal);
            out.push_back(buildSentence(b));
        }
    }
    return out;
}

std::string GeoStarReceiver::dtm() const {
    // Local datum the output is in, offsets from WGS-84 (PZ-90.11 differs by centimetres).
    if (current_.datum == "P90") return buildSentence("GPDTM,P90,,0.000,N,0.000,E,000.0,W84");
    return buildSentence("GPDTM,W84,,0.000,N,0.000,E,000.0,W84");
}

std::string GeoStarReceiver::rlm() const {
    // A test-service return link message (code F) for a simulated beacon.
    const std::string time = nmea::formatTime(nmea::timeOfDay(utcSecondOfDay(), 2), 2);
    return buildSentence("GPRLM,123456789ABCD12," + time + ",F,0000");
}

} // namespace gnss::sim

namespace gnss::geostar {

std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options) {
    return std::make_unique<sim::GeoStarReceiver>(options);
}

} // namespace gnss::geostar
