#include "nemerix_sim_receiver.h"

#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_dialect.h"
#include "nemerix_sim_navdata.h"
#include "nmea/nmea_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnss::sim {

namespace {

constexpr std::size_t kReportsPerEpoch = 6; // PNMRX30x lines interleaved per second
constexpr int kMaxGsv = 12;                 // "allowing up to 12 satellites in view"

int messageIndex(std::string_view id) {
    for (std::size_t i = 0; i < NemerixReceiver::kMessages.size(); ++i)
        if (NemerixReceiver::kMessages[i] == id) return static_cast<int>(i);
    return -1;
}

int reportIndex(std::string_view id) {
    for (std::size_t i = 0; i < NemerixReceiver::kReports.size(); ++i)
        if (NemerixReceiver::kReports[i] == id) return static_cast<int>(i);
    return -1;
}

std::string hex8(std::uint64_t v) {
    char b[16];
    std::snprintf(b, sizeof b, "%08llX", static_cast<unsigned long long>(v));
    return b;
}

std::string decimal1(double v) {
    return formatFixed(v, 1);
}

} // namespace

NemerixReceiver::NemerixReceiver(const SimOptions &options)
    : Receiver(nemerix::dialect(), options) {
    current_ = defaults();
    if (options.baud > 0) current_.baud = options.baud;
}

NemerixReceiver::Settings NemerixReceiver::defaults() const {
    Settings s;
    // Rates and sequence: the schema's defaults (2.1.8: GGA, RMC, VTG 1 s; GSA, GSV 3 s).
    for (std::size_t i = 0; i < kMessages.size(); ++i) {
        const SettingDef *d = findSetting(dialect().settings, "rate." + std::string(kMessages[i]));
        s.rates[i] = d ? std::atoi(std::string(d->defaultValue).c_str()) : 0;
        if (s.rates[i] > 0) s.sequence.push_back(static_cast<int>(i));
    }
    return s;
}

UseMask NemerixReceiver::useMask() const {
    UseMask m;
    m.gps = true;
    m.glonass = m.galileo = m.beidou = m.sbas = false;
    m.galileoHardware = m.beidouHardware = false;
    m.elevationMask = current_.minElevation;
    m.snrMask = current_.minSnr;
    return m;
}

FixKind NemerixReceiver::fixAfter(double seconds) const {
    if (coreStopped_ || isp_) return FixKind::None;
    return Receiver::fixAfter(seconds);
}

void NemerixReceiver::onReset(ResetKind kind) {
    if (kind == ResetKind::PowerCycle) {
        current_ = defaults(); // no save command: the factory settings come back
        setBaudNow(current_.baud);
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
    if (m.type == &PlainCommand::kVersionQueryType) {
        reply(s, buildSentence("PNMRX600,VT002,NMRX-SW,2.06.0011,070615"));
    } else if (m.type == &PlainCommand::kSettingsQueryType) {
        for (const std::string &line : settingsReports()) reply(s, line);
    } else if (m.type == &PlainCommand::kIspType) {
        isp_ = true; // the bootloader waits for a firmware image: no NMEA until power cycle
    } else if (m.type == &PlainCommand::kStopCoreType) {
        coreStopped_ = true;
    } else if (m.type == &RateList::kNmeaType || m.type == &RateList::kNemerixType) {
        const auto &r = static_cast<const RateList &>(m);
        const bool nmeaRates = m.type == &RateList::kNmeaType;
        for (std::size_t i = 0; i < r.count; ++i) {
            const RateEntry &e = r.entries[i];
            if (!e.value) continue;
            if (nmeaRates) {
                if (*e.value >= 0 && *e.value <= 9) applyRate(e.id, *e.value);
            } else if (*e.value >= 0 && *e.value <= 3) {
                for (int k = 0; k < 5; ++k) {
                    if (e.id != "ALL" && reportIndex(e.id) != k) continue;
                    current_.reportModes[k] = *e.value;
                    if (*e.value == 1 || *e.value == 3) queueReport(k, lastSnapshot());
                    if (*e.value == 2 || *e.value == 3) {
                        if (k == 1) ephemerisSent_.clear();
                        dataReported_ = false;
                    }
                }
            }
        }
    } else if (const auto *q = message_cast<NmeaSequence>(m)) {
        std::vector<int> seq;
        for (std::size_t i = 0; i < q->count; ++i) {
            const int k = messageIndex(q->ids[i]);
            if (k >= 0 && std::find(seq.begin(), seq.end(), k) == seq.end()) seq.push_back(k);
        }
        if (!seq.empty()) {
            current_.sequence = seq;
            current_.rates.fill(0);
            for (int k : seq) current_.rates[k] = 1; // "output every second"
        }
    } else if (const auto *p = message_cast<SerialPort>(m)) {
        const bool baudOk = p->baud && std::ranges::find(nemerix::kSupportedBauds, *p->baud) !=
                                               std::end(nemerix::kSupportedBauds);
        const bool protoOk = !p->protocol || *p->protocol == 0 || *p->protocol == 1;
        const bool parityOk = !p->parity || (*p->parity >= 0 && *p->parity <= 2);
        if (!baudOk || !protoOk || !parityOk) return; // declared invalid as a whole
        current_.baud = *p->baud;
        current_.protocol = p->protocol.value_or(0);
        current_.parity = p->parity.value_or(0);
        reply(s, std::string(), current_.baud); // no answer; the port switches
    } else if (const auto *n = message_cast<NavInit>(m)) {
        if (n->channels) current_.channels = *n->channels;
        if (n->fixProcedure == 8) {
            softwareReset(std::nullopt, "FACTORY");
            return;
        }
        if (n->fixProcedure) current_.fixProcedure = *n->fixProcedure;
        if (n->x) reset(ResetKind::Hot); // a new position restarts the receiver
    } else if (const auto *l = message_cast<LlaInit>(m)) {
        if (l->channels) current_.channels = *l->channels;
        if (l->lat && l->lon && l->altitude) reset(ResetKind::Hot);
    } else if (const auto *d = message_cast<DatumSetting>(m)) {
        if (!d->datum || (*d->datum > 218 && *d->datum != 500)) return;
        current_.datumCorrection = d->correction.value_or(0);
        current_.datum = *d->datum;
        current_.dx = d->dx.value_or(0);
        current_.dy = d->dy.value_or(0);
        current_.dz = d->dz.value_or(0);
        current_.iflatRaw = d->iflatRaw.value_or(0);
        current_.majorARaw = d->majorARaw.value_or(0);
    } else if (const auto *f = message_cast<FixSettings>(m)) {
        for (std::size_t i = 0; i < f->count; ++i) {
            const FixMask &k = f->masks[i];
            const double v = k.value.value_or(0);
            auto in = [&](double lo, double hi) { return k.value && v >= lo && v <= hi; };
            switch (k.id) {
            case 0:
                if (k.tzMinutes && std::abs(*k.tzMinutes) <= 13 * 60)
                    current_.tzMinutes = *k.tzMinutes;
                break;
            case 1:
                if (in(0, 10)) current_.maxPdop = v;
                break;
            case 2:
                if (in(0, 10)) current_.maxHdop = v;
                break;
            case 3:
                if (in(0, 10)) current_.maxVdop = v;
                break;
            case 4:
                if (in(20, 45)) current_.minSnr = static_cast<int>(v);
                break;
            case 5:
                if (in(0, 90)) current_.minElevation = static_cast<int>(v);
                break;
            case 6:
                if (in(400, 1000)) current_.noiseFloor = static_cast<int>(v);
                break;
            case 7:
                if (v == 1 || v == 2 || v == 4) current_.navMode1 = static_cast<int>(v);
                break;
            case 8:
                if (in(0, 999999)) current_.altitude2d = static_cast<int>(v);
                break;
            case 9:
                if (v == 0 || v == 1) current_.navMode2 = static_cast<int>(v);
                break;
            case 10:
                if (in(0, 999999)) current_.maxAltitude = static_cast<int>(v);
                break;
            default: break;
            }
        }
    } else if (const auto *r = message_cast<SoftwareReset>(m)) {
        softwareReset(r->bits, r->named);
    } else if (const auto *pm = message_cast<PowerMode>(m)) {
        if (pm->mode && (*pm->mode == 0 || *pm->mode == 1)) current_.powerMode = *pm->mode;
        if (pm->offPeriod && *pm->offPeriod >= 5 && *pm->offPeriod <= 10)
            current_.offPeriod = *pm->offPeriod;
    } else if (const auto *a = message_cast<Almanac>(m)) {
        if (a->sv >= 1 && a->sv <= 32) uploaded_.insert(a->sv);
    }
}

void NemerixReceiver::applyRate(std::string_view id, int value) {
    for (std::size_t i = 0; i < kMessages.size(); ++i) {
        if (id != "ALL" && id != kMessages[i]) continue;
        current_.rates[i] = value;
        const int k = static_cast<int>(i);
        if (value > 0 && std::find(current_.sequence.begin(), current_.sequence.end(), k) ==
                                 current_.sequence.end())
            current_.sequence.push_back(k);
    }
}

void NemerixReceiver::softwareReset(std::optional<int> bits, std::string_view named) {
    const Settings keepPort = current_;
    auto factory = [&] {
        current_ = defaults();
        current_.baud = keepPort.baud; // the link stays where it is
        current_.protocol = keepPort.protocol;
        current_.parity = keepPort.parity;
    };
    if (named == "FACTORY") {
        factory();
        reset(ResetKind::Cold);
    } else if (named == "COLD") {
        reset(ResetKind::Cold);
    } else if (named == "WARM") {
        reset(ResetKind::Warm);
    } else if (named == "HOT") {
        reset(ResetKind::Hot);
    } else if (bits) {
        if (*bits & 1) factory(); // reload the settings from flash (the factory settings)
        reset((*bits & 2) ? ResetKind::Cold : (*bits & 4) ? ResetKind::Warm : ResetKind::Hot);
    } else {
        reset(current_.fixProcedure == 4 ? ResetKind::Cold : ResetKind::Hot);
    }
}

// ---- Reports ------------------------------------------------------------------------------

void NemerixReceiver::queueReport(int index, const SkySnapshot &snap) {
    const double tow = gpsTimeOfWeek();
    const int week = gpsWeek();
    const int sv = [&] {
        for (const SimSatellite &s : snap.satellites)
            if (s.used && s.system == Constellation::Gps) return s.prn;
        return 1;
    }();
    switch (index) {
    case 0: // almanac of every satellite, ascending SV id
        for (int prn = 1; prn <= 32; ++prn) {
            std::string a = nemerixdata::almanac(sky(), prn, time(), tow, week);
            if (!a.empty()) queue_.push_back(std::move(a));
        }
        break;
    case 1: // ephemeris of the satellites in use (three messages each)
        for (const SimSatellite &s : snap.satellites) {
            if (!s.used || s.system != Constellation::Gps) continue;
            for (std::string &e : nemerixdata::ephemeris(sky(), s.prn, time(), tow, week))
                queue_.push_back(std::move(e));
            ephemerisSent_.insert(s.prn);
        }
        break;
    case 2: queue_.push_back(nemerixdata::ionosphere(sv)); break;
    case 3: queue_.push_back(nemerixdata::utc(sv, week, kLeapSeconds)); break;
    case 4: queue_.push_back(nemerixdata::health(sky())); break;
    default: break;
    }
}

std::vector<std::string> NemerixReceiver::settingsReports() const {
    const Settings &c = current_;
    std::string m0 = "PNMRX603,0";
    for (std::size_t i = 0; i < kMessages.size(); ++i) {
        // Position of each message in the output sequence (1-based; 0 = not in it).
        const auto it = std::find(c.sequence.begin(), c.sequence.end(), static_cast<int>(i));
        m0 += "," + std::to_string(it == c.sequence.end() ? 0 : it - c.sequence.begin() + 1);
    }
    for (int r : c.rates) m0 += "," + std::to_string(r);
    std::uint64_t modes = 0;
    for (std::size_t i = 0; i < c.reportModes.size(); ++i)
        modes |= static_cast<std::uint64_t>(c.reportModes[i]) << (2 * i);
    // UART word: speed in the low 20 bits, parity and protocol above (layout not documented).
    const std::uint64_t uart = static_cast<std::uint64_t>(c.baud) |
                               (static_cast<std::uint64_t>(c.parity) << 20) |
                               (static_cast<std::uint64_t>(c.protocol) << 24);
    m0 += "," + hex8(modes) + "," + hex8(uart);
    // Message 1: ionosphere as PNMRX302 carries it, valid once collected, time zone.
    const std::string iono = nemerixdata::ionosphere(1); // "$PNMRX302,1,a0,...*hh"
    const auto comma = iono.find(',', iono.find(',') + 1);
    const std::string coeffs = iono.substr(comma, iono.rfind('*') - comma);
    const bool collected = currentFix() != FixKind::None;
    const int tzh = c.tzMinutes / 60, tzm = c.tzMinutes % 60;
    const std::string m1 = "PNMRX603,1" + coeffs + "," + (collected ? "1" : "0") + ",2," +
                           std::to_string(tzh) + "," + std::to_string(tzm);
    const std::string m2 = "PNMRX603,2," + decimal1(c.maxPdop) + "," + decimal1(c.maxHdop) +
                           ",00000000," + decimal1(c.minSnr) + "," + decimal1(c.minElevation) +
                           "," + std::to_string(c.channels) + ",12";
    const std::string m3 = "PNMRX603,3,350,300," + std::to_string(c.noiseFloor) + ",1," +
                           std::to_string(c.altitude2d);
    const std::string m4 = "PNMRX603,4," + std::to_string(c.datumCorrection) + "," +
                           std::to_string(c.datum) + "," + std::to_string(c.dx) + "," +
                           std::to_string(c.dy) + "," + std::to_string(c.dz) + "," +
                           std::to_string(c.iflatRaw) + "," + std::to_string(c.majorARaw);
    return {buildSentence(m0), buildSentence(m1), buildSentence(m2), buildSentence(m3),
            buildSentence(m4)};
}

// ---- Output -------------------------------------------------------------------------------

void NemerixReceiver::onEpoch(const SkySnapshot &snap) {
    if (isp_ || current_.protocol != 0) return; // bootloader / binary protocol: no NMEA
    std::vector<int> order = current_.sequence;
    for (std::size_t i = 0; i < kMessages.size(); ++i)
        if (current_.rates[i] > 0 &&
            std::find(order.begin(), order.end(), static_cast<int>(i)) == order.end())
            order.push_back(static_cast<int>(i));
    for (int k : order) {
        const int rate = current_.rates[k];
        if (rate <= 0 || second_ % rate != 0) continue;
        for (const std::string &line : sentencesOf(k, snap)) send(line);
    }
    // "On change" reports: ephemeris of newly used satellites, the rest once collected.
    if (!coreStopped_ && snap.fix != FixKind::None) {
        const auto &modes = current_.reportModes;
        if (modes[1] >= 2) {
            SkySnapshot fresh = snap;
            for (SimSatellite &s : fresh.satellites)
                s.used = s.used && !ephemerisSent_.count(s.prn);
            queueReport(1, fresh);
        }
        if (!dataReported_) {
            for (int k : {0, 2, 3, 4})
                if (modes[k] >= 2) queueReport(k, snap);
            dataReported_ = true;
        }
    }
    for (std::size_t i = 0; i < kReportsPerEpoch && !queue_.empty(); ++i) {
        send(queue_.front());
        queue_.pop_front();
    }
    ++second_;
}

std::vector<std::string> NemerixReceiver::sentencesOf(int message, const SkySnapshot &snap) const {
    const std::string_view id = kMessages[message];
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
        z.tzHours = current_.tzMinutes / 60;
        z.tzMinutes = std::abs(current_.tzMinutes % 60);
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
