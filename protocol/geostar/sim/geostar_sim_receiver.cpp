#include "geostar/sim/geostar_sim_receiver.h"

#include "core/sentence_builder.h"
#include "geostar/geostar_dialect.h"
#include "geostar/geostar_encoders.h"
#include "geostar/geostar_schema.h"
#include "nmea/nmea_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnss::sim {

namespace {

constexpr double kAlmanacAfter = 30.0; // seconds of tracking until the almanacs are complete
constexpr double kSbasAfter = 20.0;    // seconds after the first fix until SBAS corrections
constexpr int kPositionDecimals = 6;   // GeoS-5 rev. 1.1: ddmm.mmmmmm

// Power-on outputs and rate: the spec's NQUERY example (3.12), read with the dialect's decoder.
constexpr std::string_view kPowerOnOutputs = "$GPSGG,NQUERY,1,3,2,R,0,R,1,0,0,0,1,1,0*71";
// The port the simulated receiver is on (the example's port 1).
constexpr int kPort = 1;
// Who the simulated module is: the spec's RQUERY example, a GeoS-5M with firmware 5.102 of
// 10.05.2018 (table 9 type F7FF).
constexpr std::string_view kReceiverName = "GEOS-5";
constexpr std::string_view kFirmware = "V.5.102";
constexpr Date kFirmwareDate{2018, 5, 10};
constexpr std::uint16_t kReceiverType = 0xF7FF;

// The code a message gets when switched on: the spec's NQUERY example shows GGA/GSA at the
// output rate and GSV/ZDA/DTM once a second; the other messages follow the same split.
char onCode(std::string_view name) {
    return (name == "GSV" || name == "ZDA" || name == "DTM" || name == "RLM") ? '1' : 'R';
}

// Every setting at its power-on value (the schema has no defaults to seed from).
void seedPowerOn(SettingsStore &store, int baud) {
    std::vector<KeyValue> outputs;
    auto read = [&outputs](const Message &m) { geostar::extractSettings(m, outputs); };
    DecodeContext ctx(&geostar::dialect(), read);
    Sentence s;
    if (s.parse(kPowerOnOutputs)) geostar::decodeSgg(s, ctx);
    for (KeyValue &kv : outputs) store.seed(kv.key, std::move(kv.value));
    store.seed("power.PSM", "0");
    store.seed("nav.ELEV", "5");
    store.seed("nav.DAT", "W84");
    store.seed("nav.NVS", "MIX");
    store.seed("port.BDR", std::to_string(baud));
    store.seed("port.STOP", "1");
}

// The one sentence an encoder built; empty (nothing is sent) if it refused, which the values the
// simulator gives never make it do.
std::string only(const EncodeResult &r) {
    return r.ok() && !r.sentences.empty() ? r.sentences.front() : std::string();
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
    : DialectReceiver(geostar::dialect(), options) {
    seedPowerOn(store_, baud());
    almanacSince_ = kAlmanacAfter;
}

UseMask GeoStarReceiver::useMask() const {
    UseMask m = DialectReceiver::useMask();
    m.gps = gnssMode() != "GLN";
    m.glonass = gnssMode() != "GPS";
    m.galileo = gnssMode() == "MIX";
    m.beidou = false;
    m.beidouHardware = false; // GeoS-5: GPS, GLONASS, Galileo, QZSS, SBAS
    m.sbas = m.gps;
    return m;
}

FixKind GeoStarReceiver::fixAfter(double seconds) const {
    const FixKind base = Receiver::fixAfter(seconds);
    if (base == FixKind::None) return base;
    // SBAS corrections (GeoS-5M) once the SBAS message has been received, GPS in use.
    if (gnssMode() != "GLN" && seconds - ttff() >= kSbasAfter) return FixKind::Differential;
    return base;
}

void GeoStarReceiver::onReset(ResetKind kind) {
    almanacValid_ = almanacValid_ || time() >= almanacSince_; // collected before the reset
    if (kind == ResetKind::PowerCycle) {
        restoreFromFlash();
        loadedFromFlash_ = flashWritten_;
        binary_ = false;
        announce_ = true;
        almanacValid_ = almanacInFlash_;
    }
    if (kind == ResetKind::Cold) almanacValid_ = false;
    hotStart_ = kind == ResetKind::Hot;
    validSinceStart_ = false;
    almanacSince_ = time() + (almanacValid_ ? 0.0 : kAlmanacAfter);
}

// ---- Commands -----------------------------------------------------------------------------

void GeoStarReceiver::onCommand(const Sentence &s, const Message *decoded, std::string_view) {
    if (binary_ || !decoded) return;
    const auto *c = message_cast<geostar::Command>(*decoded);
    if (!c || !c->def) return;
    const geostar::CommandDef &d = *c->def;
    store_.apply(*decoded); // a set command's setting; queries and actions carry none
    if (d.text == "RQUERY") {
        reply(s, only(geostar::encodeRquery(rquery())));
    } else if (d.text == "NQUERY") {
        reply(s, only(geostar::encodeNquery(nquery())));
    } else if (d.text == "SAVEFL") {
        store_.save();
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
        // No answer; the port switches at once.
        reply(s, std::string(), portSpeed());
    } else if (d.settingKey == "output.RATE") {
        rescheduleEpochs();
    }
}

// ---- RQUERY and NQUERY --------------------------------------------------------------------

geostar::Rquery GeoStarReceiver::rquery() const {
    const SkySnapshot &snap = lastSnapshot();
    const bool tracking =
            snap.used > 0 || std::any_of(snap.satellites.begin(), snap.satellites.end(),
                                         [](const SimSatellite &x) { return x.tracked; });
    const bool almanac = almanacValid_ || time() >= almanacSince_;
    const bool navData = tracking && sinceTracking() >= ttff();
    const UseMask m = useMask();
    geostar::Rquery q;
    q.receiverName = kReceiverName;
    q.firmware = kFirmware;
    q.firmwareDate = kFirmwareDate;
    geostar::StatusWord &w = q.status; // table 7
    w.flashWriteInProgress = time() < flashWriteUntil_;
    w.sbasCorrectionsUsed = w.differential = currentFix() == FixKind::Differential;
    w.active = true; // sleep is not simulated
    w.solutionAvailable = currentFix() != FixKind::None;
    w.validSinceStart = validSinceStart_;
    w.clockRestoredHotStart = hotStart_;
    w.gpsIonoUtcAvailable = tracking && sinceTracking() >= ttff() + 12.5; // from page 18
    w.dateFromNavMessage = w.timeFromNavMessage = navData;
    w.galileoAlmanac = almanac && m.galileo;
    w.glonassAlmanac = almanac && m.glonass;
    w.gpsAlmanac = almanac && m.gps;
    w.antenna = geostar::AntennaState::Ok;
    w.glonassAgcOk = w.gpsAgcOk = true;
    w.settingsLoadedFromFlash = loadedFromFlash_;
    w.pllOk = w.rtcOk = w.backupRamOk = true;
    geostar::ConfigRegister1 &c1 = q.config1; // table 8; rate, power saving, systems: the store
    c1.antennaPower = true;
    c1.fixByRequest = false; // power saving type RELAXED FIX
    c1.dynamicsCode = 1;     // pedestrian/car
    c1.kalmanFilter = true;
    c1.firstFix2DAllowed = true;
    c1.ppsEnabled = true; // GPS time scale, positive
    c1.sbas = true;
    geostar::ConfigRegister2 &c2 = q.config2; // table 9; datum: the store
    c2.receiverTypeCode = kReceiverType;
    c2.differentialAllowed = true;
    c2.useAllSatellites = true; // with or without corrections
    c2.sbasPrnAuto = true;
    geostar::reportSettings(store_.values(), q);
    return q;
}

geostar::Nquery GeoStarReceiver::nquery() const {
    geostar::Nquery n;
    n.port = kPort;
    for (std::size_t i = 0; i < n.kMessages; ++i)
        n.codes[i] = n.kNames[i].empty() ? '0' : onCode(n.kNames[i]);
    n.codeCount = n.kMessages;
    geostar::reportSettings(store_.values(), n);
    return n;
}

// RQUERY and NQUERY of the receiver's own accord (after power-on, every second with all off).
void GeoStarReceiver::sendReports() {
    for (const std::string &line :
         {only(geostar::encodeRquery(rquery())), only(geostar::encodeNquery(nquery()))})
        if (!line.empty()) send(line);
}

// ---- Output -------------------------------------------------------------------------------

void GeoStarReceiver::onEpoch(const SkySnapshot &snap) {
    if (snap.fix != FixKind::None) validSinceStart_ = true;
    if (binary_) return;
    const double t = utcSeconds(); // every N seconds of UTC, as the receiver's clock counts
    if (announce_) {               // once after power-on (3.11, 3.12)
        sendReports();
        announce_ = false;
        lastAllOffReport_ = t;
    }
    const geostar::Nquery outputs = nquery();
    bool allStandardOff = true;
    for (std::size_t i = 0; i < outputs.kMessages; ++i) {
        const std::string_view name = outputs.kNames[i];
        if (name.empty()) continue;
        const char code = outputs.codes[i];
        if (name != "RLM" && code != '0') allStandardOff = false;
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
            for (const std::string &line : sentencesOf(name, snap))
                if (!line.empty()) send(line);
    }
    // Every standard message off: RQUERY and NQUERY once a second instead (3.11, 3.12).
    if (allStandardOff && t - lastAllOffReport_ >= 1.0 - 1e-6) {
        sendReports();
        lastAllOffReport_ = t;
    }
}

std::string GeoStarReceiver::talker() const {
    if (nmeaVersion() == 2) return "GP";
    if (gnssMode() == "GPS") return "GP";
    if (gnssMode() == "GLN") return "GL";
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
        if (nmeaVersion() == 4)
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
        nmea::Rmc m = rmcOf(snap, t, 2);
        if (nmeaVersion() == 4) m.navStatus = 'V'; // "not formed by the receiver"
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
    if (gnssMode() != "MIX") return out;
    const bool enabled[3] = {m.gps, m.glonass, m.galileo};
    for (int i = 0; i < 3; ++i) {
        if (!enabled[i]) continue;
        nmea::Gns sub; // the system's satellites; no corrections per system (not simulated)
        sub.time = g.time;
        sub.satsUsed = counts[i];
        out.push_back(only(geostar::encodeSubsidiaryGns(systems[i].second, sub)));
    }
    return out;
}

std::vector<std::string> GeoStarReceiver::gsa(const SkySnapshot &snap) const {
    const bool valid = snap.fix != FixKind::None;
    const UseMask m = useMask();
    const int v = nmeaVersion();
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
    const int v = nmeaVersion();
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
    if (store_.value("nav.DAT") == "P90")
        return buildSentence("GPDTM,P90,,0.000,N,0.000,E,000.0,W84");
    return buildSentence("GPDTM,W84,,0.000,N,0.000,E,000.0,W84");
}

std::string GeoStarReceiver::rlm() const {
    // A test-service return link message (code F, a short message) for the spec's beacon.
    geostar::Rlm m;
    m.beaconId = "123456789ABCD12";
    m.time = nmea::timeOfDay(utcSecondOfDay(), 2);
    m.messageCode = 0xF;
    m.parameters = "0000";
    return only(geostar::encodeRlm(m));
}

} // namespace gnss::sim

namespace gnss::geostar {

std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options) {
    return std::make_unique<sim::GeoStarReceiver>(options);
}

} // namespace gnss::geostar
