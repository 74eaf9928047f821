#include "nemerix/sim/nemerix_sim_receiver.h"

#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_dialect.h"
#include "nemerix/nemerix_dialect_parts.h"
#include "nemerix/sim/nemerix_sim_navdata.h"
#include "nmea/nmea_messages.h"

#include <algorithm>
#include <cmath>

namespace gnss::sim {

namespace {

constexpr std::size_t kReportsPerEpoch = 6; // PNMRX30x lines interleaved per second
constexpr int kMaxGsv = 12;                 // "allowing up to 12 satellites in view"

// What PNMRX600 reports (the spec gives no layout; this receiver's own words).
constexpr std::string_view kVersion[] = {"VT002", "NMRX-SW", "2.06.0011", "070615"};

// The simulated VT002's factory values of the settings the schema gives no default: the masks
// act on the fix, and PNMRX603 reports them.
constexpr std::pair<std::string_view, std::string_view> kFactoryValues[] = {
        {"nmrx.300", "0"},
        {"nmrx.301", "0"},
        {"nmrx.302", "0"},
        {"nmrx.303", "0"},
        {"nmrx.304", "0"},
        {"fix.maxPdop", "10"},
        {"fix.maxHdop", "10"},
        {"fix.maxVdop", "10"},
        {"fix.minSnr", "25"},
        {"fix.minElevation", "5"},
        {"fix.noiseFloor", "600"},
        {"fix.altitude2d", "0"},
        {"fix.maxAltitude", "18000"},
        {"nav.mode", "1"},
        {"nav.dynamics", "0"},
        {"nav.channels", "12"},
        {"power.offPeriod", "5"},
};

// What PNMRX603 reports besides the settings: the receiver's constants.
constexpr int kMaxSvForFix = 12;
constexpr std::int64_t kAcqThreshold1 = 350, kAcqThreshold2 = 300;
constexpr std::uint64_t kKalmanMode = 1, kNumBlocks = 2; // 20-year blocks since 1980

std::string rateKey(std::string_view id) {
    return "rate." + std::string(id);
}

bool listed(const std::vector<std::string_view> &ids, std::string_view id) {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}

} // namespace

NemerixReceiver::NemerixReceiver(const SimOptions &options)
    : DialectReceiver(nemerix::dialect(), options) {
    // The datasheet's averages (hot 12 s, warm 38 s, cold 60 s); the spread, 15 % of each, is
    // ours: it gives none.
    TtffModel family;
    family.hot = {12, 1.8};
    family.warm = {38, 5.7};
    family.cold = {60, 9};
    setFamilyTtff(family);
    for (const auto &[key, value] : kFactoryValues) store_.seed(key, std::string(value));
    if (options.baud > 0) store_.set("serial.baud", std::to_string(options.baud));
}

UseMask NemerixReceiver::useMask() const {
    UseMask m = DialectReceiver::useMask();
    m.glonass = m.galileo = m.beidou = m.sbas = false; // GPS only
    m.galileoHardware = m.beidouHardware = false;
    return m;
}

FixKind NemerixReceiver::fixAfter(double seconds) const {
    if (coreStopped_ || isp_) return FixKind::None;
    return Receiver::fixAfter(seconds);
}

void NemerixReceiver::onReset(ResetKind kind) {
    if (kind == ResetKind::PowerCycle) {
        restoreFromFlash(); // no save command: the factory settings come back
        fixProcedure_ = 0;
        isp_ = false;
    }
    coreStopped_ = false;
    ephemerisSent_.clear();
    dataReported_ = false;
    queue_.clear();
    second_ = 0;
}

// ---- Commands -----------------------------------------------------------------------------

void NemerixReceiver::onCommand(const Sentence &s, const Message *decoded, std::string_view) {
    if (isp_ || !decoded) return;
    using namespace nemerix;
    const Message &m = *decoded;
    // The settings it carries, as the dialect reads them (a report sent to the receiver is the
    // receiver's own output, not a command: it sets nothing).
    if (!message_cast<SettingsReport>(m)) store_.apply(m);
    if (m.type == &PlainCommand::kVersionQueryType) {
        VersionReport v(VersionReport::kSoftwareType);
        for (std::string_view field : kVersion) v.fieldsText[v.count++] = field;
        for (const std::string &line : encodeVersionReport(v).sentences) reply(s, line);
    } else if (m.type == &PlainCommand::kSettingsQueryType) {
        for (const std::string &line : settingsReports()) reply(s, line);
    } else if (m.type == &PlainCommand::kIspType) {
        isp_ = true; // the bootloader waits for a firmware image: no NMEA until power cycle
    } else if (m.type == &PlainCommand::kStopCoreType) {
        coreStopped_ = true;
    } else if (m.type == &RateList::kNemerixType) {
        reportModesChanged(static_cast<const RateList &>(m));
    } else if (m.type == &RateList::kNmeaType) {
        keepRatedInSequence(static_cast<const RateList &>(m));
    } else if (const auto *p = message_cast<SerialPort>(m)) {
        // No answer; the port switches (a command without a baud sets nothing).
        if (p->baud) reply(s, std::string(), portSpeed());
    } else if (const auto *n = message_cast<NavInit>(m)) {
        if (n->fixProcedure == 8) {
            softwareReset(std::nullopt, "FACTORY");
            return;
        }
        if (n->fixProcedure) fixProcedure_ = *n->fixProcedure;
        if (n->x) reset(ResetKind::Hot); // a new position restarts the receiver
    } else if (const auto *l = message_cast<LlaInit>(m)) {
        if (l->lat && l->lon && l->altitude) reset(ResetKind::Hot);
    } else if (const auto *r = message_cast<SoftwareReset>(m)) {
        softwareReset(r->bits, r->named);
    } else if (const auto *a = message_cast<Almanac>(m)) {
        if (a->sv >= 1 && a->sv <= 32) uploaded_.insert(a->sv);
    }
}

// PNMRX107: "now" sends the reports at once, "on change" waits for data to report.
void NemerixReceiver::reportModesChanged(const nemerix::RateList &modes) {
    for (std::size_t i = 0; i < modes.count; ++i) {
        const nemerix::RateEntry &e = modes.entries[i];
        if (!e.value) continue;
        for (std::size_t k = 0; k < nemerix::kNavDataMessageIds.size(); ++k) {
            if (e.id != "ALL" && e.id != nemerix::kNavDataMessageIds[k]) continue;
            if (*e.value == 1 || *e.value == 3) queueReport(k, lastSnapshot());
            if (*e.value == 2 || *e.value == 3) {
                if (k == 1) ephemerisSent_.clear();
                dataReported_ = false;
            }
        }
    }
}

// PNMRX103: a message given a rate joins the output sequence at its end.
void NemerixReceiver::keepRatedInSequence(const nemerix::RateList &rates) {
    std::vector<std::string_view> ids = sequence();
    bool grown = false;
    for (std::size_t i = 0; i < rates.count; ++i) {
        const nemerix::RateEntry &e = rates.entries[i];
        if (!e.value || *e.value <= 0) continue;
        for (std::string_view id : nemerix::kNmeaMessageIds)
            if ((e.id == "ALL" || e.id == id) && !listed(ids, id)) {
                ids.push_back(id);
                grown = true;
            }
    }
    if (!grown) return;
    std::string list;
    for (std::string_view id : ids) list += (list.empty() ? "" : ";") + std::string(id);
    store_.set("output.sequence", list);
}

// The settings from flash (the factory settings: nothing is ever saved), the link where it is.
void NemerixReceiver::factorySettings() {
    std::vector<std::pair<std::string, std::string>> link;
    for (const SettingDef &def : dialect().settings)
        if (def.command && def.command->changesLink)
            link.emplace_back(def.key, store_.value(def.key));
    store_.restore();
    for (auto &[key, value] : link) store_.set(key, value);
    fixProcedure_ = 0;
}

void NemerixReceiver::softwareReset(std::optional<int> bits, std::string_view named) {
    if (named == "FACTORY") {
        factorySettings();
        reset(ResetKind::Cold);
    } else if (named == "COLD") {
        reset(ResetKind::Cold);
    } else if (named == "WARM") {
        reset(ResetKind::Warm);
    } else if (named == "HOT") {
        reset(ResetKind::Hot);
    } else if (bits) {
        if (*bits & 1) factorySettings(); // reload the settings from flash
        reset((*bits & 2) ? ResetKind::Cold : (*bits & 4) ? ResetKind::Warm : ResetKind::Hot);
    } else {
        reset(fixProcedure_ == 4 ? ResetKind::Cold : ResetKind::Hot);
    }
}

// ---- Reports ------------------------------------------------------------------------------

void NemerixReceiver::queue(const EncodeResult &built) {
    for (const std::string &line : built.sentences) queue_.push_back(line);
}

void NemerixReceiver::queueReport(std::size_t index, const SkySnapshot &snap) {
    using namespace nemerix;
    const double tow = gpsTimeOfWeek();
    const int week = gpsWeek();
    const int sv = [&] {
        for (const SimSatellite &s : snap.satellites)
            if (s.used && s.system == Constellation::Gps) return s.prn;
        return 1;
    }();
    switch (index) {
    case 0: // almanac of every satellite, ascending SV id
        for (int prn = 1; prn <= 32; ++prn)
            if (const auto a = nemerixdata::almanac(sky(), prn, time(), tow, week))
                queue(encodeAlmanac(*a));
        break;
    case 1: // ephemeris of the satellites in use (three messages each)
        for (const SimSatellite &s : snap.satellites) {
            if (!s.used || s.system != Constellation::Gps) continue;
            for (const EphemerisSubframe &e :
                 nemerixdata::ephemeris(sky(), s.prn, time(), tow, week))
                queue(encodeEphemerisSubframe(e));
            ephemerisSent_.insert(s.prn);
        }
        break;
    case 2: queue(encodeIonosphere(nemerixdata::ionosphere(sv))); break;
    case 3: queue(encodeUtc(nemerixdata::utc(sv, week, kLeapSeconds))); break;
    case 4: queue(encodeHealth(nemerixdata::health(sky()))); break;
    default: break;
    }
}

std::vector<std::string> NemerixReceiver::settingsReports() const {
    nemerix::SettingsReportState state;
    state.iono = nemerixdata::ionosphere(1).raw;
    state.ionoValid = currentFix() != FixKind::None; // collected once the sky is tracked
    state.numBlocks = kNumBlocks;
    state.maxSvForFix = kMaxSvForFix;
    state.acqThreshold1 = kAcqThreshold1;
    state.acqThreshold2 = kAcqThreshold2;
    state.kalmanMode = kKalmanMode;
    std::vector<KeyValue> values;
    for (const auto &[key, value] : store_.values()) values.push_back({key, value});
    return nemerix::encodeSettingsReports(values, state).sentences;
}

int NemerixReceiver::reportMode(std::size_t index) const {
    return static_cast<int>(
            store_.integer("nmrx." + std::string(nemerix::kNavDataMessageIds[index])));
}

std::vector<std::string_view> NemerixReceiver::sequence() const {
    std::vector<std::string_view> ids;
    for (const std::string &id : nemerix::sequenceIds(store_.value("output.sequence")))
        for (std::string_view known : nemerix::kNmeaMessageIds)
            if (id == known && !listed(ids, known)) ids.push_back(known);
    return ids;
}

std::vector<std::string_view> NemerixReceiver::outputOrder() const {
    std::vector<std::string_view> order = sequence();
    for (std::string_view id : nemerix::kNmeaMessageIds)
        if (store_.integer(rateKey(id)) > 0 && !listed(order, id)) order.push_back(id);
    return order;
}

// ---- Output -------------------------------------------------------------------------------

void NemerixReceiver::onEpoch(const SkySnapshot &snap) {
    // Bootloader / binary protocol: no NMEA.
    if (isp_ || store_.integer("serial.protocol") != 0) return;
    for (std::string_view id : outputOrder()) {
        const auto rate = store_.integer(rateKey(id));
        if (rate <= 0 || second_ % rate != 0) continue;
        for (const std::string &line : sentencesOf(id, snap)) send(line);
    }
    // "On change" reports: ephemeris of newly used satellites, the rest once collected.
    if (!coreStopped_ && snap.fix != FixKind::None) {
        if (reportMode(1) >= 2) {
            SkySnapshot fresh = snap;
            for (SimSatellite &s : fresh.satellites)
                s.used = s.used && !ephemerisSent_.count(s.prn);
            queueReport(1, fresh);
        }
        if (!dataReported_) {
            for (std::size_t k : {0, 2, 3, 4})
                if (reportMode(k) >= 2) queueReport(k, snap);
            dataReported_ = true;
        }
    }
    for (std::size_t i = 0; i < kReportsPerEpoch && !queue_.empty(); ++i) {
        send(queue_.front());
        queue_.pop_front();
    }
    ++second_;
}

std::vector<std::string> NemerixReceiver::sentencesOf(std::string_view id,
                                                      const SkySnapshot &snap) const {
    const EpochTime t{utcSecondOfDay(), utcDate()};
    StandardStyle st;
    st.numbering = Numbering::Nmea40; // NMEA 3.0: no system or signal ids
    st.format.timeDecimals = 3;       // hhmmss.sss
    st.format.positionDecimals = 4;
    st.gpTalkerForGgaRmc = true;
    // GPS only: GLONASS/SBAS satellites of the sky are not received.
    SkySnapshot gps = snap;
    gps.satellites.erase(
            std::remove_if(gps.satellites.begin(), gps.satellites.end(),
                           [](const SimSatellite &s) { return s.system != Constellation::Gps; }),
            gps.satellites.end());
    if (id == "GGA") return {ggaSentence(gps, t, st)};
    if (id == "RMC") return {rmcSentence(gps, t, st)};
    if (id == "GLL") return {gllSentence(gps, t, st)};
    if (id == "VTG") return {vtgSentence(gps, st)};
    if (id == "GSA") return gsaSentences(gps, st);
    if (id == "ZDA") {
        nmea::Zda z;
        z.time = nmea::timeOfDay(t.utcSecondOfDay, 2);
        z.date = t.date;
        const int tz = nemerix::parseTimeZone(store_.value("fix.timeZone")).value_or(0);
        z.tzHours = tz / 60;
        z.tzMinutes = std::abs(tz % 60);
        nmea::EncodeFormat f;
        return {nmea::encodeZda("GP", z, f)};
    }
    if (id == "GSV") { // at most 12: the highest satellites, listed by PRN
        std::sort(gps.satellites.begin(), gps.satellites.end(),
                  [](const SimSatellite &a, const SimSatellite &b) {
                      return a.elevation > b.elevation;
                  });
        if (gps.satellites.size() > static_cast<std::size_t>(kMaxGsv))
            gps.satellites.resize(kMaxGsv);
        std::sort(gps.satellites.begin(), gps.satellites.end(),
                  [](const SimSatellite &a, const SimSatellite &b) { return a.prn < b.prn; });
        return gsvSentences(gps, st);
    }
    return {};
}

} // namespace gnss::sim

namespace gnss::nemerix {

std::unique_ptr<sim::Receiver> makeSimulatedReceiver(const sim::SimOptions &options) {
    return std::make_unique<sim::NemerixReceiver>(options);
}

} // namespace gnss::nemerix
