#include "nvs/sim/nvs_sim_receiver.h"

#include "core/sentence_builder.h"
#include "core/wgs84.h"
#include "nmea/nmea_messages.h"
#include "nvs/nvs_dialect.h"
#include "nvs/nvs_encoders.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace gnss::sim {

namespace {

std::string fixed(double v, int d) {
    return formatFixed(v, d);
}

std::string outputKey(int port) {
    return "output." + std::string(nvs::portName(port));
}
std::string baudKey(int port) {
    return "port." + std::string(nvs::portName(port)) + ".baud";
}
std::string protocolKey(int port) {
    return "port." + std::string(nvs::portName(port)) + ".protocol";
}
constexpr std::string_view kStationsKey = "idl.stations";

// Three numbers "a,b,c" (BASEXYZ, BASEBLH in radians); false for anything else.
bool parseNumbers(const std::string &text, double (&v)[3]) {
    std::size_t at = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = i < 2 ? text.find(',', at) : text.size();
        if (comma == std::string::npos) return false;
        const std::string part = text.substr(at, comma - at);
        char *end = nullptr;
        v[i] = std::strtod(part.c_str(), &end);
        if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(v[i])) return false;
        at = comma + 1;
    }
    return true;
}

double distance(const wgs84::Ecef &a, const wgs84::Ecef &b) {
    return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

} // namespace

NvsReceiver::NvsReceiver(const SimOptions &options) : DialectReceiver(nvs::dialect(), options) {
    // What the schema leaves to the receiver. The base station the rover hears: its coordinates
    // are the values of BASEXYZ/BASEBLH.
    const Observer &o = options.observer;
    double lat = o.latDeg, lon = o.lonDeg, h = o.altMsl + o.geoidSep;
    offsetGeodetic(lat, lon, h, -baseNorth_, -baseEast_, -baseUp_);
    const wgs84::Ecef xyz = wgs84::toEcef({lat, lon, h});
    store_.seed("rtk.BASEXYZ", fixed(xyz.x, 4) + "," + fixed(xyz.y, 4) + "," + fixed(xyz.z, 4));
    store_.seed("rtk.BASEBLH", fixed(wgs84::radians(lat), 10) + "," +
                                       fixed(wgs84::radians(lon), 10) + "," + fixed(h, 4));
    // "Default value depends on RTK FW release date".
    if (store_.value("rtk.INITGPSWEEK").empty()) store_.seed("rtk.INITGPSWEEK", "2048");
    const nvs::RzbEntry output[] = {{"GGA", 1},
                                    {"GSA", 1},
                                    {"GSV", 5},
                                    {"RMC", 1},
                                    {"VTG", 1},
                                    {"ZDA", 5},
                                    {std::string(nvs::Bss::kType.name), 5}};
    store_.seed(outputKey(kCurrentPort), nvs::formatOutputList(output));
    // Started at another speed (gnss-sim --baud): that speed is the one saved, the factory's stays
    // the schema's; a speed the receiver cannot be set to is this unit's own from the factory.
    if (options.baud > 0) {
        if (store_.set(baudKey(kCurrentPort), std::to_string(options.baud)))
            store_.save();
        else
            store_.seed(baudKey(kCurrentPort), std::to_string(options.baud));
    }
    nextRtcm_ = ttff() + 0.35; // corrections arrive between epochs
}

int NvsReceiver::mode() const {
    return static_cast<int>(store_.integer("rtk.MODE"));
}

UseMask NvsReceiver::useMask() const {
    UseMask m;
    m.gps = store_.value("rtk.SYSGPS") != "0";
    m.glonass = store_.value("rtk.SYSGLO") != "0";
    m.sbas = store_.value("rtk.SYSSBAS") != "0";
    m.galileo = m.beidou = false; // a GPS/GLONASS receiver
    m.galileoHardware = m.beidouHardware = false;
    const bool rtk = mode() != 0;
    m.elevationMask = store_.real(rtk ? "rtk.ELGPS" : "rtk.ELMASKA");
    m.snrMask = store_.real(rtk ? "rtk.SNR" : "rtk.SNRMASKA");
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
    return store_.real("rtk.RTCMAGE");
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
    if (kind == ResetKind::PowerCycle) restoreFromFlash();
    // A base averaging its position starts over (MODE 3 after any restart).
    averagingSince_ = mode() == 3 ? time() : -1;
    averaged_ = 0;
    averageSum_[0] = averageSum_[1] = averageSum_[2] = 0;
    epochIndex_ = 0;
    sendTestResults_ = true;
    rtcmTotal_ = rtcmErrors_ = 0;
    lastRtcm_ = flowSince_ = -1;
    hostRtcm_ = rtcm::RtcmFramer();
    nextRtcm_ = time() + ttff() + 0.35;
}

std::string NvsReceiver::canonical(std::string_view a) const {
    // The standard sentences this receiver sends (sentencesOf), and its own: every address of
    // the dialect's rules, named whole or by its last three characters (4.5).
    static constexpr std::string_view kStandard[] = {"GGA", "GSA", "GSV", "RMC",
                                                     "VTG", "ZDA", "HDT"};
    for (auto s : kStandard)
        if (a == s) return std::string(a);
    for (const SentenceRule &r : dialect().rules)
        if (r.address == a || (a.size() == 3 && r.address.ends_with(a)))
            return std::string(r.address);
    return {};
}

std::optional<int> NvsReceiver::portOf(std::optional<int> port) {
    const int p = port.value_or(0) == 0 ? kCurrentPort : *port;
    if (nvs::portNumber(nvs::portName(p)) != p) return std::nullopt;
    return p;
}

std::vector<nvs::RzbEntry> NvsReceiver::outputList(int port) const {
    std::vector<nvs::RzbEntry> list;
    nvs::parseOutputList(outputKey(port), store_.value(outputKey(port)), list);
    return list;
}

std::vector<nvs::Station> NvsReceiver::stations() const {
    std::vector<nvs::Station> list;
    nvs::parseStations(store_.value(kStationsKey), list);
    return list;
}

std::string NvsReceiver::reportOf(std::string_view key) const {
    const SettingDef *row = findSetting(dialect().settings, key);
    std::vector<std::string> keys;
    for (const SettingDef &def : dialect().settings)
        if (row && def.command == row->command) keys.emplace_back(def.key);
    EncodeResult r = store_.report(keys);
    return r.ok() && !r.sentences.empty() ? r.sentences.front() : std::string();
}

// ---- Output (what each address sends: nvs_sim_output.cpp) ----------------------------------

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
    if (isBase()) baseEpoch(snap);
    const long long protocol = store_.integer(protocolKey(kCurrentPort));
    if (protocol == 7 && !isBase()) { // RTCM on this port: raw-data frames instead of NMEA
        if (epochIndex_ % 5 == 0) {
            std::uniform_int_distribution<int> len(60, 200);
            send(rtcm3Frame(random(), 1077, len(random())));
        }
    } else if (protocol == 1) {
        if (sendTestResults_)
            for (const std::string &s : sentencesOf("PNVGTST", snap)) send(s);
        const SkySnapshot shown = reported(snap);
        for (const nvs::RzbEntry &e : outputList(kCurrentPort)) {
            if (e.rate <= 0 || epochIndex_ % e.rate != 0) continue;
            for (const std::string &s : sentencesOf(e.address, shown)) send(s);
        }
    }
    sendTestResults_ = false;
    markPending_ = false;
    ++epochIndex_;
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
    const double oldInterval = epochInterval();
    const int oldMode = mode();
    const std::string oldXyz = store_.value("rtk.BASEXYZ"), oldBlh = store_.value("rtk.BASEBLH");
    const std::string oldAverage = store_.value("rtk.AVGTIME");
    store_.apply(m); // a value the receiver does not take leaves the one it had
    if (store_.value("rtk.BASEXYZ") != oldXyz)
        syncBasePosition(true);
    else if (store_.value("rtk.BASEBLH") != oldBlh)
        syncBasePosition(false);
    if (mode() == 3 && store_.value("rtk.AVGTIME") != oldAverage) onReset(ResetKind::Hot);
    // The answer names every parameter asked, as often as asked, with the value in force;
    // unknown names are left out.
    std::vector<nvs::RtkSet> answer;
    for (const nvs::RtkParam &p : m.params)
        if (nvs::isRtkParameter(p.name))
            answer.push_back({std::string(p.name), store_.value("rtk." + std::string(p.name))});
    if (answer.empty()) return;
    if (EncodeResult r = nvs::encodeRtk(answer); r.ok()) reply(s, r.sentences.front());
    if (epochInterval() != oldInterval) rescheduleEpochs();
    if (mode() != oldMode) reset(ResetKind::Hot); // the engine restarts in its new mode
}

void NvsReceiver::handleRzb(const nvs::Rzb &m) {
    const auto port = portOf(m.port);
    if (!port) return;
    std::vector<nvs::RzbEntry> list = outputList(*port);
    if (m.entries.empty()) list.clear();
    for (const nvs::RzbEntry &e : m.entries) {
        const std::string a = canonical(e.address);
        if (a.empty() || e.rate < 1) continue;
        auto it = std::ranges::find(list, a, &nvs::RzbEntry::address);
        if (it != list.end())
            it->rate = e.rate;
        else if (list.size() < nvs::kMaxOutputMessages)
            list.push_back({a, e.rate});
    }
    store_.set(outputKey(*port), nvs::formatOutputList(list));
}

void NvsReceiver::handleRza(const Sentence &s, const nvs::Rza &m) {
    const auto port = portOf(m.port);
    if (!port) return;
    // Speed and protocol are taken together or not at all: the schema's values (the encoder
    // checks them) at a speed the receiver runs at (the record's list).
    const auto &speeds = dialect().supportedBauds;
    const bool supported =
            m.baud && std::find(speeds.begin(), speeds.end(), *m.baud) != speeds.end();
    if (supported && m.protocol && nvs::encodeRza(*port, *m.baud, *m.protocol).ok()) {
        nvs::Rza taken = m;
        taken.port = *port;
        store_.apply(taken);
    }
    // The answer carries the settings now in force (other values than asked = refused), then
    // the port switches (spec 2.1: within 100 ms after the reply).
    const std::string answer = reportOf(baudKey(*port));
    if (!answer.empty()) reply(s, answer, *port == kCurrentPort ? portSpeed() : 0);
}

void NvsReceiver::handleNme(const Sentence &s, const nvs::Nme &m) {
    // All or nothing: the fields given with those in force must make a valid PNVGNME.
    auto inForce = [this](const char *key) { return static_cast<int>(store_.integer(key)); };
    if (nvs::encodeNme(m.timeDecimals.value_or(inForce("nmea.time_decimals")),
                       m.positionDecimals.value_or(inForce("nmea.position_decimals")),
                       m.talkerMode.value_or(inForce("nmea.talker_mode")))
                .ok())
        store_.apply(m);
    reply(s, reportOf("nmea.time_decimals"));
}

void NvsReceiver::handleCfg(const Sentence &s, const nvs::Cfg &m) {
    if (m.action.size() != 1) return;
    const EncodeResult confirm = nvs::encodeCfg(m.action.front()); // W, E or R
    if (!confirm.ok()) return;
    reply(s, confirm.sentences.front());
    if (m.action == "W")
        store_.save();
    else
        store_.saveDefaults();
    if (m.action == "R") reset(ResetKind::PowerCycle);
}

void NvsReceiver::handlePps(const Sentence &s, const nvs::Pps &m) {
    // All or nothing: every field given must be one the receiver takes (empty = unchanged).
    const nvs::PpsSettings given{m.type,     m.mode,     m.reference, m.adjust,
                                 m.duration, m.validity, m.cableDelay};
    if (nvs::encodePps(given).ok()) store_.apply(m);
    reply(s, reportOf("pps.type"));
}

void NvsReceiver::handleIdl(const Sentence &s, const nvs::Idl &m) {
    std::vector<nvs::Station> list = stations();
    nvs::Idl answer;
    answer.kind = m.kind;
    switch (m.kind) {
    case nvs::IdlKind::Mode:
        store_.apply(m); // 0 or 1 (the schema's), else the mode in force stays
        reply(s, reportOf("idl.mode"));
        break;
    case nvs::IdlKind::Add: {
        // Omitted: the station heard and the GLONASS bias in force.
        const int id = m.stationId.value_or(kBaseStation);
        const double icb = m.icb.value_or(store_.real("rtk.ICBGLO"));
        const EncodeResult r = nvs::encodeIdlAdd(id, icb);
        if (!r.ok()) return; // out of range: nothing added, no answer
        auto it = std::ranges::find(list, id, &nvs::Station::id);
        if (it != list.end())
            it->icb = icb;
        else if (list.size() < nvs::kMaxStations)
            list.push_back({id, icb});
        else
            return;
        store_.set(kStationsKey, nvs::formatStations(list));
        reply(s, r.sentences.front());
        break;
    }
    case nvs::IdlKind::Remove: {
        const auto before = list.size();
        if (m.stationId)
            std::erase_if(list, [&](const nvs::Station &x) { return x.id == *m.stationId; });
        store_.set(kStationsKey, nvs::formatStations(list));
        answer.status = list.size() < before ? "OK" : "ERROR";
        reply(s, nvs::encodeIdl(answer).sentences.front());
        break;
    }
    case nvs::IdlKind::Clear:
        store_.set(kStationsKey, "");
        answer.status = "OK";
        reply(s, nvs::encodeIdl(answer).sentences.front());
        break;
    case nvs::IdlKind::Show:
        // One item per station, "$PNVGIDL,0" for none.
        answer.kind = nvs::IdlKind::Item;
        answer.count = static_cast<int>(list.size());
        if (list.empty()) reply(s, nvs::encodeIdl(answer).sentences.front());
        for (std::size_t i = 0; i < list.size(); ++i) {
            answer.index = static_cast<int>(i + 1);
            answer.stationId = list[i].id;
            answer.icb = list[i].icb.value_or(store_.real("rtk.ICBGLO"));
            if (EncodeResult r = nvs::encodeIdl(answer); r.ok()) reply(s, r.sentences.front());
        }
        break;
    case nvs::IdlKind::Item: break; // a reply, not a command
    }
}

// ---- Base station -------------------------------------------------------------------------

std::optional<wgs84::Geodetic> NvsReceiver::basePosition() const {
    double xyz[3];
    if (!parseNumbers(store_.value("rtk.BASEXYZ"), xyz)) return std::nullopt;
    return wgs84::toGeodetic({xyz[0], xyz[1], xyz[2]});
}

void NvsReceiver::setBasePosition(const wgs84::Geodetic &g) {
    const wgs84::Ecef xyz = wgs84::toEcef(g);
    store_.set("rtk.BASEXYZ", fixed(xyz.x, 4) + "," + fixed(xyz.y, 4) + "," + fixed(xyz.z, 4));
    store_.set("rtk.BASEBLH", fixed(wgs84::radians(g.latDeg), 10) + "," +
                                      fixed(wgs84::radians(g.lonDeg), 10) + "," +
                                      fixed(g.height, 4));
}

void NvsReceiver::syncBasePosition(bool fromXyz) {
    // The point just written, and the other form's point as it stands.
    double xyz[3], blh[3];
    const bool haveXyz = parseNumbers(store_.value("rtk.BASEXYZ"), xyz);
    const bool haveBlh = parseNumbers(store_.value("rtk.BASEBLH"), blh);
    if (fromXyz ? !haveXyz : !haveBlh) return;
    const wgs84::Geodetic fromBlh{wgs84::degrees(blh[0]), wgs84::degrees(blh[1]), blh[2]};
    // The other already names this point (both written together, or as the reply printed it):
    // its text stays as written.
    if (haveXyz && haveBlh && distance(wgs84::toEcef(fromBlh), {xyz[0], xyz[1], xyz[2]}) < 0.01)
        return;
    if (fromXyz) {
        if (auto g = wgs84::toGeodetic({xyz[0], xyz[1], xyz[2]})) setBasePosition(*g);
    } else {
        setBasePosition(fromBlh);
    }
}

SkySnapshot NvsReceiver::reported(const SkySnapshot &snap) const {
    // Past BASETH the receiver gives its own position (spec: "the current position is given in
    // NMEA").
    if (!isBase() || snap.fix == FixKind::None || averagingSince_ >= 0 || beyondThreshold_ ||
        store_.integer("rtk.BASENMEA") != 0)
        return snap;
    const auto base = basePosition();
    if (!base) return snap;
    SkySnapshot s = snap;
    s.lat = base->latDeg;
    s.lon = base->lonDeg;
    s.altMsl = base->height - s.geoidSep;
    s.errNorth = s.errEast = s.errUp = 0;
    return s;
}

void NvsReceiver::baseEpoch(const SkySnapshot &snap) {
    if (snap.fix == FixKind::None) return; // no position of its own yet: nothing to send
    const wgs84::Geodetic own{snap.lat, snap.lon, snap.altMsl + snap.geoidSep};
    if (averagingSince_ >= 0) { // MODE 3: averaging, no RTCM until it ends
        const wgs84::Ecef e = wgs84::toEcef(own);
        averageSum_[0] += e.x, averageSum_[1] += e.y, averageSum_[2] += e.z;
        ++averaged_;
        if (time() - averagingSince_ < store_.real("rtk.AVGTIME", 30) * 60) return;
        const double n = double(averaged_);
        if (auto g =
                    wgs84::toGeodetic({averageSum_[0] / n, averageSum_[1] / n, averageSum_[2] / n}))
            setBasePosition(*g);
        averagingSince_ = -1;
    }
    const auto base = basePosition();
    if (!base) return;
    const double threshold = store_.real("rtk.BASETH", 500);
    beyondThreshold_ =
            threshold > 0 && distance(wgs84::toEcef(*base), wgs84::toEcef(own)) > threshold;
    if (beyondThreshold_) return;
    BaseStationConfig config;
    config.latDeg = base->latDeg;
    config.lonDeg = base->lonDeg;
    config.height = base->height;
    config.stationId = static_cast<unsigned>(store_.integer("rtk.BASEID", kBaseStation));
    config.seed = options().seed;
    config.biasesInterval = 0;
    config.observations = BaseStationConfig::Observations::Legacy;
    config.observationInterval = std::max(1, static_cast<int>(store_.integer("rtk.RTCMRATE", 1)));
    if (!baseTx_) {
        baseTx_ = std::make_unique<RtcmBaseStation>(config);
        baseTx_->startAt(time()); // on the simulated clock: its epochs at whole seconds
        baseTx_->advance(0);
    } else {
        baseTx_->reconfigure(config);
        baseTx_->advance(time() - baseTx_->time());
    }
    const std::string frames = baseTx_->takeOutput();
    if (frames.empty()) return;
    for (int port = 1; port <= 3; ++port) {
        if (nvs::portNumber(nvs::portName(port)) != port) continue;
        if (store_.integer(protocolKey(port)) != 7) continue;
        sendBytes(frames, port == kCurrentPort ? 0 : port);
    }
}

} // namespace gnss::sim

namespace gnss::nvs {

std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options) {
    return std::make_unique<sim::NvsReceiver>(options);
}

} // namespace gnss::nvs
