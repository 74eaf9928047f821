#include "nvs_sim_receiver.h"

#include "core/sentence_builder.h"
#include "core/wgs84.h"
#include "nmea/nmea_messages.h"
#include "nvs/nvs_dialect.h"
#include "nvs/nvs_encoders.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnss::sim {

namespace {

constexpr int kBaseStation = 2;        // the simulated base's station id (PNVGRTK BASEID default)
constexpr std::size_t kMaxOutput = 20; // spec 2.1: at most 20 output messages
constexpr std::size_t kMaxStations = 32;

// The address an output-list entry stands for: "RMC" → "RMC", "BSS"/"PNVGBSS" → "PNVGBSS".
std::string canonical(std::string_view a) {
    static constexpr std::string_view kStandard[] = {"GGA", "GSA", "GSV", "RMC",
                                                     "VTG", "ZDA", "HDT"};
    static constexpr std::string_view kOwn[] = {"VER", "NME", "RZA", "BSS", "TST", "CFG", "PPS",
                                                "IMU", "BRS", "BLS", "VOG", "RTK", "IDL", "TME",
                                                "TMU", "TMC", "SDP", "SDV", "SDH", "DOP"};
    if (a.size() == 7 && a.substr(0, 4) == "PNVG") return std::string(a);
    for (auto s : kStandard)
        if (a == s) return std::string(a);
    for (auto s : kOwn)
        if (a == s) return "PNVG" + std::string(a);
    return {};
}

std::string fixed(double v, int d) {
    return formatFixed(v, d);
}

std::string station4(int id) {
    char b[8];
    std::snprintf(b, sizeof b, "%04d", id);
    return b;
}

std::string joined(const std::vector<std::string_view> &values) {
    std::string s;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i) s += ',';
        s += values[i];
    }
    return s;
}

} // namespace

NvsReceiver::NvsReceiver(const SimOptions &options) : Receiver(nvs::dialect(), options) {
    current_ = saved_ = defaults();
    if (options.baud > 0)
        current_.ports[kCurrentPort].baud = saved_.ports[kCurrentPort].baud = options.baud;
    nextRtcm_ = ttff() + 0.35; // corrections arrive between epochs
}

NvsReceiver::Settings NvsReceiver::defaults() const {
    Settings s;
    for (std::string_view name : nvs::rtkParameterNames()) {
        const SettingDef *def = findSetting(dialect().settings, "rtk." + std::string(name));
        s.rtk[std::string(name)] = def ? std::string(def->defaultValue) : std::string();
    }
    // The base station the rover hears: its coordinates are the defaults of BASEXYZ/BASEBLH.
    const Observer &o = options().observer;
    double lat = o.latDeg, lon = o.lonDeg, h = o.altMsl + o.geoidSep;
    offsetGeodetic(lat, lon, h, -baseNorth_, -baseEast_, -baseUp_);
    const wgs84::Ecef xyz = wgs84::toEcef({lat, lon, h});
    s.rtk["BASEXYZ"] = fixed(xyz.x, 4) + "," + fixed(xyz.y, 4) + "," + fixed(xyz.z, 4);
    s.rtk["BASEBLH"] = fixed(wgs84::radians(lat), 10) + "," + fixed(wgs84::radians(lon), 10) + "," +
                       fixed(h, 4);
    if (s.rtk["INITGPSWEEK"].empty()) s.rtk["INITGPSWEEK"] = "2048";
    for (int p = 1; p <= 3; ++p) s.ports[p] = Port{};
    s.ports[kCurrentPort].output = {{"GGA", 1}, {"GSA", 1}, {"GSV", 5},    {"RMC", 1},
                                    {"VTG", 1}, {"ZDA", 5}, {"PNVGBSS", 5}};
    return s;
}

std::string NvsReceiver::rtkValue(std::string_view name) const {
    auto it = current_.rtk.find(name);
    return it == current_.rtk.end() ? std::string() : it->second;
}

int NvsReceiver::mode() const {
    return std::atoi(rtkValue("MODE").c_str());
}

double NvsReceiver::epochInterval() const {
    const int hz = std::atoi(rtkValue("PVTRATE").c_str());
    return hz > 0 ? 1.0 / hz : 0.2;
}

UseMask NvsReceiver::useMask() const {
    UseMask m;
    m.gps = rtkValue("SYSGPS") != "0";
    m.glonass = rtkValue("SYSGLO") != "0";
    m.sbas = rtkValue("SYSSBAS") != "0";
    m.galileo = m.beidou = false; // a GPS/GLONASS receiver
    m.galileoHardware = m.beidouHardware = false;
    const bool rtk = mode() != 0;
    m.elevationMask = std::atof(rtkValue(rtk ? "ELGPS" : "ELMASKA").c_str());
    m.snrMask = std::atof(rtkValue(rtk ? "SNR" : "SNRMASKA").c_str());
    return m;
}

FixKind NvsReceiver::fixAfter(double seconds) const {
    const FixKind base = Receiver::fixAfter(seconds);
    if (base == FixKind::None) return base;
    const int m = mode();
    if (m != 2 && m != 4) return base; // autonomous or base station
    if (!options().internalBase) {
        // A real rover: float after a few seconds of corrections, fixed after about twenty,
        // autonomous again once the last correction is older than RTCMAGE.
        if (lastRtcm_ < 0 || time() - lastRtcm_ > correctionAgeLimit()) return base;
        const double flowing = time() - flowSince_;
        if (flowing >= 20) return FixKind::Fixed;
        if (flowing >= 3) return FixKind::Float;
        return base;
    }
    const double sinceFix = seconds - ttff();
    if (sinceFix >= 15) return FixKind::Fixed;
    if (sinceFix >= 5) return FixKind::Float;
    return FixKind::Autonomous;
}

double NvsReceiver::correctionAgeLimit() const {
    const double limit = std::atof(rtkValue("RTCMAGE").c_str());
    return limit > 0 ? limit : 45;
}

void NvsReceiver::onHostBytes(std::string_view bytes) {
    if (options().internalBase) return;
    const bool rover = mode() == 2 || mode() == 4; // a base or an autonomous receiver ignores them
    hostRtcm_.feed(bytes, [this, rover](const rtcm::RtcmFrame &) {
        ++rtcmTotal_;
        if (!rover) return;
        if (lastRtcm_ < 0 || time() - lastRtcm_ > correctionAgeLimit()) flowSince_ = time();
        lastRtcm_ = time();
    });
    // Frames whose CRC failed count as received and bad (PNVGBSS fields 1 and 2).
    const auto failures = std::int64_t(hostRtcm_.stats().crcFailures);
    rtcmTotal_ += failures - rtcmErrors_;
    rtcmErrors_ = failures;
}

void NvsReceiver::onReset(ResetKind kind) {
    if (kind == ResetKind::PowerCycle) {
        current_ = saved_;
        setBaudNow(current_.ports[kCurrentPort].baud);
    }
    epochIndex_ = 0;
    sendTestResults_ = true;
    rtcmTotal_ = rtcmErrors_ = 0;
    lastRtcm_ = flowSince_ = -1;
    hostRtcm_ = rtcm::RtcmFramer();
    nextRtcm_ = time() + ttff() + 0.35;
}

StandardStyle NvsReceiver::style() const {
    StandardStyle st;
    st.numbering = Numbering::Nmea40;
    st.format.timeDecimals = current_.timeDecimals;
    st.format.positionDecimals = current_.positionDecimals;
    st.gpTalkerForGgaRmc = current_.talkerMode == 0;
    return st;
}

std::string NvsReceiver::timeField() const {
    return nmea::formatTime(nmea::timeOfDay(utcSecondOfDay(), current_.timeDecimals),
                            current_.timeDecimals);
}

std::string NvsReceiver::proprietary(std::string_view body) const {
    return buildSentence(body);
}

// ---- Output -------------------------------------------------------------------------------

void NvsReceiver::onEpoch(const SkySnapshot &snap) {
    // The simulated base's corrections: one burst a second once the rover tracks (RTK modes).
    const bool rover = options().internalBase && (mode() == 2 || mode() == 4);
    while (rover && time() >= nextRtcm_) { // corrections received up to now
        rtcmTotal_ += 3;                   // 1005 + 1002 + 1010
        std::uniform_int_distribution<int> err(0, 199);
        if (err(random()) == 0) ++rtcmErrors_;
        lastRtcm_ = nextRtcm_;
        nextRtcm_ += 1.0;
    }
    // Time mark events: about one a second, between epochs.
    if (time() >= nextMark_) {
        ++markCounter_;
        lastMark_ = nextMark_;
        markSnap_ = snap;
        markPending_ = true;
        std::uniform_real_distribution<double> gap(0.8, 1.2);
        nextMark_ += gap(random());
    }
    const Port &port = current_.ports[kCurrentPort];
    if (port.protocol == 7) { // RTCM on this port: raw-data frames instead of NMEA
        if (epochIndex_ % 5 == 0) {
            std::uniform_int_distribution<int> len(60, 200);
            send(rtcm3Frame(random(), 1077, len(random())));
        }
    } else if (port.protocol == 1) {
        if (sendTestResults_)
            for (const std::string &s : sentencesOf("PNVGTST", snap)) send(s);
        for (const nvs::RzbEntry &e : port.output) {
            if (e.rate <= 0 || epochIndex_ % e.rate != 0) continue;
            for (const std::string &s : sentencesOf(e.address, snap)) send(s);
        }
    }
    sendTestResults_ = false;
    markPending_ = false;
    ++epochIndex_;
}

std::vector<std::string> NvsReceiver::sentencesOf(std::string_view address,
                                                  const SkySnapshot &snap) {
    const std::string a = canonical(address);
    const StandardStyle st = style();
    const EpochTime t{utcSecondOfDay(), utcDate()};
    const char mode = modeIndicator(snap.fix);
    const bool valid = snap.fix != FixKind::None;
    const bool rtk = snap.fix == FixKind::Float || snap.fix == FixKind::Fixed;
    const bool heading = this->mode() == 4 && snap.fix == FixKind::Fixed;
    const double age = lastRtcm_ >= 0 ? time() - lastRtcm_ : -1;
    auto withDifferential = [&](nmea::Gga g) {
        if (rtk && age >= 0) {
            g.dgpsAge = age;
            g.dgpsStation = kBaseStation;
        }
        return g;
    };
    if (a == "GGA") {
        const auto talker = st.gpTalkerForGgaRmc ? "GP" : solutionTalker(snap, st.numbering);
        return {nmea::encodeGga(talker, withDifferential(ggaOf(snap, t, st.format.timeDecimals)),
                                st.format)};
    }
    if (a == "RMC") return {rmcSentence(snap, t, st)};
    if (a == "VTG") return {vtgSentence(snap, st)};
    if (a == "ZDA") return {zdaSentence(snap, t, st)};
    if (a == "GSA") return gsaSentences(snap, st);
    if (a == "GSV") return gsvSentences(snap, st);
    if (a == "HDT") {
        std::normal_distribution<double> n(0, 0.1);
        return {hdtSentence(heading ? std::optional<double>(heading_ + n(random())) : std::nullopt,
                            st)};
    }
    if (a == "PNVGVER") return {proprietary("PNVGVER,NVS,RTA,0029,CSM24,0101")};
    if (a == "PNVGTST") return {proprietary("PNVGTST,ID,1254367,ANT,0")};
    if (a == "PNVGNME") {
        auto r = nvs::encodeNme(current_.timeDecimals, current_.positionDecimals,
                                current_.talkerMode);
        return r.sentences;
    }
    if (a == "PNVGBSS") {
        std::string b = "PNVGBSS," + std::to_string(rtcmTotal_) + "," +
                        std::to_string(rtcmErrors_) + "," +
                        std::to_string(rtcmTotal_ - rtcmErrors_) + ",";
        if (rtcmTotal_ > 0) {
            const double d =
                    std::sqrt(baseNorth_ * baseNorth_ + baseEast_ * baseEast_ + baseUp_ * baseUp_);
            b += fixed(d, 3) + "," + (age >= 0 ? fixed(std::min(age, 999.9), 1) : std::string());
        } else {
            b += ",";
        }
        return {proprietary(b)};
    }
    if (a == "PNVGBRS") {
        if (!valid) return {proprietary("PNVGBRS," + timeField() + ",,,,,,,N")};
        const double n = baseNorth_ + snap.errNorth, e = baseEast_ + snap.errEast,
                     u = baseUp_ + snap.errUp;
        const double len = std::sqrt(n * n + e * e + u * u);
        double course = wgs84::degrees(std::atan2(e, n));
        if (course < 0) course += 360;
        const double pitch = wgs84::degrees(std::asin(u / len));
        return {proprietary("PNVGBRS," + timeField() + "," + fixed(n, 3) + "," + fixed(e, 3) + "," +
                            fixed(u, 3) + "," + fixed(len, 3) + "," + fixed(course, 2) + "," +
                            fixed(pitch, 2) + "," + std::string(1, mode))};
    }
    if (a == "PNVGBLS" || a == "PNVGSDH") {
        // ANT1→ANT2: BASELINE metres (0 = unconstrained: the antennas are 1 m apart).
        double len = std::atof(rtkValue("BASELINE").c_str());
        if (len <= 0) len = 1.0;
        const char m = this->mode() == 4 ? mode : 'N';
        const bool ok = this->mode() == 4 && valid;
        std::normal_distribution<double> noise(0, heading ? 0.1 : 2.0);
        const double c = heading_ + noise(random());
        if (a == "PNVGSDH")
            return {proprietary("PNVGSDH," + timeField() + "," +
                                (ok ? fixed(heading ? 0.2 / len : 3.0, 3) : std::string()) + "," +
                                std::string(1, m))};
        if (!ok) return {proprietary("PNVGBLS," + timeField() + ",,,,,,,N")};
        const double pitch = wgs84::radians(-4.0);
        const double h = len * std::cos(pitch);
        return {proprietary(
                "PNVGBLS," + timeField() + "," + fixed(h * std::cos(wgs84::radians(c)), 3) + "," +
                fixed(h * std::sin(wgs84::radians(c)), 3) + "," + fixed(len * std::sin(pitch), 3) +
                "," + fixed(len, 3) + "," + fixed(c, 2) + "," + fixed(wgs84::degrees(pitch), 2) +
                "," + std::string(1, m))};
    }
    if (a == "PNVGIMU") {
        std::normal_distribution<double> att(0, 0.3), acc(0, 0.05);
        return {proprietary("PNVGIMU," + timeField() + "," + fixed(0.4 + att(random()), 2) + "," +
                            fixed(0.35 + att(random()), 2) + "," +
                            fixed(heading_ + att(random()), 2) + "," + fixed(acc(random()), 3) +
                            "," + fixed(acc(random()), 3) + "," + fixed(acc(random()) - 0.2, 3))};
    }
    if (a == "PNVGVOG") {
        if (!valid) return {proprietary("PNVGVOG," + timeField() + ",,,,N")};
        return {proprietary("PNVGVOG," + timeField() + "," + fixed(snap.velNorth, 3) + "," +
                            fixed(snap.velEast, 3) + "," + fixed(snap.velUp, 3) + "," +
                            std::string(1, mode))};
    }
    if (a == "PNVGSDP") {
        if (!valid) return {proprietary("PNVGSDP," + timeField() + ",,,,N")};
        return {proprietary("PNVGSDP," + timeField() + "," + fixed(snap.sigmaNorth, 3) + "," +
                            fixed(snap.sigmaEast, 3) + "," + fixed(snap.sigmaUp, 3) + "," +
                            std::string(1, mode))};
    }
    if (a == "PNVGSDV") {
        if (!valid) return {proprietary("PNVGSDV," + timeField() + ",,,,N")};
        return {proprietary("PNVGSDV," + timeField() + "," + fixed(snap.sigmaVel, 3) + "," +
                            fixed(snap.sigmaVel, 3) + "," + fixed(snap.sigmaVel * 1.5, 3) + "," +
                            std::string(1, mode))};
    }
    if (a == "PNVGDOP") {
        if (!valid) return {proprietary("PNVGDOP," + timeField() + ",,,,,,,,N")};
        const Dops &d = snap.dops;
        return {proprietary("PNVGDOP," + timeField() + "," + fixed(d.gdop, 2) + "," +
                            fixed(d.pdop, 2) + "," + fixed(d.hdop, 2) + "," + fixed(d.vdop, 2) +
                            "," + fixed(d.tdop, 2) + "," + fixed(d.ndop, 2) + "," +
                            fixed(d.edop, 2) + "," + std::string(1, mode))};
    }
    if (a == "PNVGTME" || a == "PNVGTMU" || a == "PNVGTMC") {
        if (!markPending_) return {};
        const double markSod = std::fmod(kStartSecondOfDay + lastMark_, 86400.0);
        if (a == "PNVGTME") {
            const double tow =
                    std::fmod(5 * 86400.0 + kStartSecondOfDay + lastMark_ + kLeapSeconds, 604800.0);
            return {proprietary("PNVGTME," + std::to_string(markCounter_) + "," + fixed(tow, 9))};
        }
        if (a == "PNVGTMU")
            return {proprietary("PNVGTMU," + std::to_string(markCounter_) + "," +
                                nmea::formatTime(nmea::timeOfDay(markSod, 9), 9))};
        EpochTime mt{markSod, t.date};
        nmea::Gga g = withDifferential(ggaOf(markSnap_, mt, st.format.timeDecimals));
        const std::string gga = nmea::encodeGga("GP", g, st.format);
        // Same fields as GGA after the address (spec 4.18): reuse the GGA layout.
        const std::string fields = gga.substr(6, gga.size() - 6 - 3);
        return {proprietary("PNVGTMC" + fields)};
    }
    if (a == "PNVGPPS") {
        nvs::PpsSettings p{current_.ppsType,      current_.ppsMode,     current_.ppsReference,
                           current_.ppsAdjust,    current_.ppsDuration, current_.ppsValidity,
                           current_.ppsCableDelay};
        return nvs::encodePps(p).sentences;
    }
    return {};
}

// ---- Commands -----------------------------------------------------------------------------

void NvsReceiver::onCommand(const Sentence &s, const Message *decoded, std::string_view) {
    if (!decoded) return; // a line the receiver cannot read is ignored
    if (const auto *q = message_cast<nmea::Query>(*decoded)) {
        for (const std::string &line : sentencesOf(q->address, lastSnapshot())) reply(s, line);
    } else if (const auto *v = message_cast<nvs::Ver>(*decoded)) {
        if (v->request) reply(s, sentencesOf("PNVGVER", lastSnapshot()).front());
    } else if (const auto *m = message_cast<nvs::Rtk>(*decoded)) {
        handleRtk(s, *m);
    } else if (const auto *m = message_cast<nvs::Rzb>(*decoded)) {
        handleRzb(*m);
    } else if (const auto *m = message_cast<nvs::Rza>(*decoded)) {
        handleRza(s, *m);
    } else if (const auto *m = message_cast<nvs::Nme>(*decoded)) {
        handleNme(s, *m);
    } else if (const auto *m = message_cast<nvs::Cfg>(*decoded)) {
        handleCfg(s, *m);
    } else if (const auto *m = message_cast<nvs::Pps>(*decoded)) {
        handlePps(s, *m);
    } else if (const auto *m = message_cast<nvs::Idl>(*decoded)) {
        handleIdl(s, *m);
    } else if (const auto *m = message_cast<nvs::Rst>(*decoded)) {
        if (m->type == 'F')
            reset(ResetKind::Cold);
        else if (m->type == 'W')
            reset(ResetKind::Warm);
    }
}

void NvsReceiver::handleRtk(const Sentence &s, const nvs::Rtk &m) {
    std::vector<nvs::RtkSet> answer;
    const double oldInterval = epochInterval();
    const int oldMode = mode();
    for (const nvs::RtkParam &p : m.params) {
        const std::string name(p.name);
        if (!nvs::isRtkParameter(name)) continue; // unknown: not in the answer
        if (!p.values.empty()) {
            const std::string value = joined(p.values);
            if (nvs::validateRtkValue(name, value).empty()) current_.rtk[name] = value;
        }
        answer.push_back({name, current_.rtk[name]});
    }
    if (answer.empty()) return;
    auto r = nvs::encodeRtk(answer);
    if (r.ok()) reply(s, r.sentences.front());
    if (epochInterval() != oldInterval) rescheduleEpochs();
    if (mode() != oldMode) reset(ResetKind::Hot); // the engine restarts in its new mode
}

void NvsReceiver::handleRzb(const nvs::Rzb &m) {
    const int portNo = m.port.value_or(0) == 0 ? kCurrentPort : *m.port;
    if (portNo < 1 || portNo > 3) return;
    Port &port = current_.ports[portNo];
    if (m.entries.empty()) {
        port.output.clear();
        return;
    }
    for (const nvs::RzbEntry &e : m.entries) {
        const std::string a = canonical(e.address);
        if (a.empty() || e.rate < 1) continue;
        auto it = std::find_if(port.output.begin(), port.output.end(),
                               [&](const nvs::RzbEntry &x) { return canonical(x.address) == a; });
        if (it != port.output.end())
            it->rate = e.rate;
        else if (port.output.size() < kMaxOutput)
            port.output.push_back({a, e.rate});
    }
}

void NvsReceiver::handleRza(const Sentence &s, const nvs::Rza &m) {
    const int portNo = m.port.value_or(0) == 0 ? kCurrentPort : *m.port;
    if (portNo < 1 || portNo > 3) return;
    Port &port = current_.ports[portNo];
    const bool baudOk = m.baud && std::ranges::find(nvs::kSupportedBauds, *m.baud) !=
                                          std::end(nvs::kSupportedBauds);
    const bool protoOk = m.protocol && (*m.protocol == 0 || *m.protocol == 1 || *m.protocol == 7);
    if (baudOk && protoOk) {
        port.baud = *m.baud;
        port.protocol = *m.protocol;
    }
    // The answer carries the settings now in force (other values than asked = refused), then
    // the port switches (spec 2.1: within 100 ms after the reply).
    auto r = nvs::encodeRza(portNo, port.baud, port.protocol);
    if (r.ok()) reply(s, r.sentences.front(), portNo == kCurrentPort ? port.baud : 0);
}

void NvsReceiver::handleNme(const Sentence &s, const nvs::Nme &m) {
    const int t = m.timeDecimals.value_or(current_.timeDecimals);
    const int p = m.positionDecimals.value_or(current_.positionDecimals);
    const int k = m.talkerMode.value_or(current_.talkerMode);
    if (nvs::encodeNme(t, p, k).ok()) {
        current_.timeDecimals = t;
        current_.positionDecimals = p;
        current_.talkerMode = k;
    }
    reply(s, sentencesOf("PNVGNME", lastSnapshot()).front());
}

void NvsReceiver::handleCfg(const Sentence &s, const nvs::Cfg &m) {
    const std::string action(m.action);
    if (action != "W" && action != "E" && action != "R") return;
    reply(s, nvs::encodeCfg(action[0]).sentences.front());
    if (action == "W")
        saved_ = current_;
    else
        saved_ = defaults();
    if (action == "R") reset(ResetKind::PowerCycle);
}

void NvsReceiver::handlePps(const Sentence &s, const nvs::Pps &m) {
    nvs::PpsSettings p{m.type.value_or(current_.ppsType),
                       m.mode.value_or(current_.ppsMode),
                       m.reference.value_or(current_.ppsReference),
                       m.adjust.value_or(current_.ppsAdjust),
                       m.duration.value_or(current_.ppsDuration),
                       m.validity.value_or(current_.ppsValidity),
                       m.cableDelay.value_or(current_.ppsCableDelay)};
    if (nvs::encodePps(p).ok()) {
        current_.ppsType = *p.type;
        current_.ppsMode = *p.mode;
        current_.ppsReference = *p.reference;
        current_.ppsAdjust = *p.adjust;
        current_.ppsDuration = *p.duration;
        current_.ppsValidity = *p.validity;
        current_.ppsCableDelay = *p.cableDelay;
    }
    reply(s, sentencesOf("PNVGPPS", lastSnapshot()).front());
}

void NvsReceiver::handleIdl(const Sentence &s, const nvs::Idl &m) {
    auto &list = current_.stations;
    switch (m.kind) {
    case nvs::IdlKind::Mode:
        if (m.mode && (*m.mode == 0 || *m.mode == 1)) current_.idlMode = *m.mode;
        reply(s, nvs::encodeIdlMode(current_.idlMode).sentences.front());
        break;
    case nvs::IdlKind::Add: {
        const int id = m.stationId.value_or(kBaseStation);
        const double icb = m.icb.value_or(std::atof(rtkValue("ICBGLO").c_str()));
        auto r = nvs::encodeIdlAdd(id, icb);
        if (!r.ok()) return; // out of range: nothing added, no answer
        auto it = std::find_if(list.begin(), list.end(),
                               [&](const Station &x) { return x.id == id; });
        if (it != list.end())
            it->icb = icb;
        else if (list.size() < kMaxStations)
            list.push_back({id, icb});
        else
            return;
        reply(s, r.sentences.front());
        break;
    }
    case nvs::IdlKind::Remove: {
        const auto before = list.size();
        if (m.stationId)
            list.erase(std::remove_if(list.begin(), list.end(),
                                      [&](const Station &x) { return x.id == *m.stationId; }),
                       list.end());
        reply(s,
              buildSentence(list.size() < before ? "PNVGIDL,REMOVE,OK" : "PNVGIDL,REMOVE,ERROR"));
        break;
    }
    case nvs::IdlKind::Clear:
        list.clear();
        reply(s, buildSentence("PNVGIDL,CLEAR,OK"));
        break;
    case nvs::IdlKind::Show:
        if (list.empty()) reply(s, buildSentence("PNVGIDL,0"));
        for (std::size_t i = 0; i < list.size(); ++i)
            reply(s, buildSentence("PNVGIDL," + std::to_string(list.size()) + "," +
                                   std::to_string(i + 1) + "," + station4(list[i].id) + "," +
                                   fixed(list[i].icb, 4)));
        break;
    case nvs::IdlKind::Item: break; // a reply, not a command
    }
}

} // namespace gnss::sim

namespace gnss::nvs {

std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options) {
    return std::make_unique<sim::NvsReceiver>(options);
}

} // namespace gnss::nvs
