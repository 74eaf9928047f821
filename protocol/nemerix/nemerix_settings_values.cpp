// Settings as values, both ways: what a decoded PNMRX603 report or a decoded command carries
// (extractSettings: the settings engine reads reports with it, a simulated receiver applies
// commands with it), and the PNMRX603 report of a set of values (encodeSettingsReports, what a
// simulated receiver answers). One mapping, side by side, so the two cannot drift apart.
//
// Commands: PNMRX100 sets the port only with a baud (the receiver takes all three or nothing);
// PNMRX108 outputs the listed messages every second and the others not at all (2.3.7), so it
// sets the rates too; PNMRX106 with an internal datum carries no user-datum fields. The VT002
// has no command that reads a setting back: what a command sets is what it says.
#include "core/field_parse.h"
#include "core/sentence_builder.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_dialect_parts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnss::nemerix {

namespace {

void put(std::vector<KeyValue> &out, std::string key, std::string value) {
    out.push_back({std::move(key), std::move(value)});
}

std::string shortNumber(double d, int digits = 6) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*g", digits, d);
    return buf;
}

// "h:m" of a signed offset in minutes, as validateFix accepts it ("-0:30", never "-0:0").
std::string timeZoneText(int hours, int minutes) {
    const bool negative = hours < 0 || minutes < 0;
    return std::string(negative ? "-" : "") + std::to_string(std::abs(hours)) + ":" +
           std::to_string(std::abs(minutes));
}

// User datum fields: sent as (1/f - 290) x 1e6 and (a - 6370000) x 1000 (PNMRX106). A report
// shows 1/f to 6 digits (298.257); a command sets it to the last digit it sent (298.257224, 9
// digits), which the receiver then holds.
std::string inverseFlattening(std::int64_t raw, int digits = 6) {
    return shortNumber(290.0 + static_cast<double>(raw) / 1e6, digits);
}
std::string semiMajorAxis(std::int64_t raw) {
    return formatFixed(6370000.0 + static_cast<double>(raw) / 1000.0, 3);
}

void fromReport(const SettingsReport &m, std::vector<KeyValue> &out) {
    switch (m.number) {
    case 0:
        for (std::size_t i = 0; i < kNmeaMessageIds.size(); ++i)
            if (m.delay[i])
                put(out, "rate." + std::string(kNmeaMessageIds[i]), std::to_string(*m.delay[i]));
        break;
    case 1:
        if (m.tzHours && m.tzMinutes)
            put(out, "fix.timeZone", timeZoneText(*m.tzHours, *m.tzMinutes));
        break;
    case 2:
        if (m.maxPdop) put(out, "fix.maxPdop", shortNumber(*m.maxPdop));
        if (m.maxHdop) put(out, "fix.maxHdop", shortNumber(*m.maxHdop));
        if (m.minCno) put(out, "fix.minSnr", shortNumber(std::round(*m.minCno)));
        if (m.minElevation) put(out, "fix.minElevation", shortNumber(std::round(*m.minElevation)));
        if (m.maxTm) put(out, "nav.channels", std::to_string(*m.maxTm));
        break;
    case 3:
        if (m.noiseFloor) put(out, "fix.noiseFloor", std::to_string(*m.noiseFloor));
        if (m.defaultAltitude) put(out, "fix.altitude2d", std::to_string(*m.defaultAltitude));
        break;
    case 4:
        if (m.correction) put(out, "datum.correction", std::to_string(*m.correction));
        if (m.datum) put(out, "datum.mapDatum", std::to_string(*m.datum));
        if (m.dx) put(out, "datum.dx", std::to_string(*m.dx));
        if (m.dy) put(out, "datum.dy", std::to_string(*m.dy));
        if (m.dz) put(out, "datum.dz", std::to_string(*m.dz));
        if (m.iflatRaw) put(out, "datum.inverseFlattening", inverseFlattening(*m.iflatRaw));
        if (m.majorARaw) put(out, "datum.semiMajorAxis", semiMajorAxis(*m.majorARaw));
        break;
    }
}

// PNMRX103 rates / PNMRX107 modes: "ALL" names every message of its table.
template <std::size_t N>
void fromRates(const RateList &r, const std::array<std::string_view, N> &ids, const char *key,
               std::vector<KeyValue> &out) {
    for (std::size_t i = 0; i < r.count; ++i) {
        const RateEntry &e = r.entries[i];
        if (!e.value) continue;
        for (std::string_view id : ids)
            if (e.id == "ALL" || e.id == id)
                put(out, key + std::string(id), std::to_string(*e.value));
    }
}

void fromSequence(const NmeaSequence &q, std::vector<KeyValue> &out) {
    std::vector<std::string_view> listed;
    for (std::size_t i = 0; i < q.count; ++i)
        if (std::find(listed.begin(), listed.end(), q.ids[i]) == listed.end())
            listed.push_back(q.ids[i]);
    std::string list;
    for (std::string_view id : listed) list += (list.empty() ? "" : ";") + std::string(id);
    put(out, "output.sequence", list);
    for (std::string_view id : kNmeaMessageIds) {
        const bool on = std::find(listed.begin(), listed.end(), id) != listed.end();
        put(out, "rate." + std::string(id), on ? "1" : "0");
    }
}

void fromFixMasks(const FixSettings &f, std::vector<KeyValue> &out) {
    for (std::size_t i = 0; i < f.count; ++i) {
        const FixMask &k = f.masks[i];
        const char *key = fixMaskKey(k.id);
        if (!key) continue;
        if (k.id == 0) {
            if (k.tzMinutes) put(out, key, timeZoneText(*k.tzMinutes / 60, *k.tzMinutes % 60));
        } else if (k.value) {
            // DOPs are tenths (6.5); every other mask is a whole number.
            put(out, key,
                k.id <= 3 ? shortNumber(*k.value) : std::to_string(std::llround(*k.value)));
        }
    }
}

void fromDatum(const DatumSetting &d, std::vector<KeyValue> &out) {
    if (!d.datum) return;
    put(out, "datum.correction", std::to_string(d.correction.value_or(0)));
    put(out, "datum.mapDatum", std::to_string(*d.datum));
    if (d.dx) put(out, "datum.dx", std::to_string(*d.dx));
    if (d.dy) put(out, "datum.dy", std::to_string(*d.dy));
    if (d.dz) put(out, "datum.dz", std::to_string(*d.dz));
    if (d.iflatRaw) put(out, "datum.inverseFlattening", inverseFlattening(*d.iflatRaw, 9));
    if (d.majorARaw) put(out, "datum.semiMajorAxis", semiMajorAxis(*d.majorARaw));
}

} // namespace

void extractSettings(const Message &m, std::vector<KeyValue> &out) {
    if (const auto *r = message_cast<SettingsReport>(m)) {
        fromReport(*r, out);
    } else if (const auto *p = message_cast<SerialPort>(m)) {
        if (!p->baud) return;
        put(out, "serial.protocol", std::to_string(p->protocol.value_or(0)));
        put(out, "serial.baud", std::to_string(*p->baud));
        put(out, "serial.parity", std::to_string(p->parity.value_or(0)));
    } else if (m.type == &RateList::kNmeaType) {
        fromRates(static_cast<const RateList &>(m), kNmeaMessageIds, "rate.", out);
    } else if (m.type == &RateList::kNemerixType) {
        fromRates(static_cast<const RateList &>(m), kNavDataMessageIds, "nmrx.", out);
    } else if (const auto *q = message_cast<NmeaSequence>(m)) {
        fromSequence(*q, out);
    } else if (const auto *f = message_cast<FixSettings>(m)) {
        fromFixMasks(*f, out);
    } else if (const auto *d = message_cast<DatumSetting>(m)) {
        fromDatum(*d, out);
    } else if (const auto *n = message_cast<NavInit>(m)) {
        if (n->channels) put(out, "nav.channels", std::to_string(*n->channels));
    } else if (const auto *l = message_cast<LlaInit>(m)) {
        if (l->channels) put(out, "nav.channels", std::to_string(*l->channels));
    } else if (const auto *pm = message_cast<PowerMode>(m)) {
        if (pm->mode) put(out, "power.mode", std::to_string(*pm->mode));
        if (pm->offPeriod) put(out, "power.offPeriod", std::to_string(*pm->offPeriod));
    }
}

// ---- Values → PNMRX603 ----------------------------------------------------------------------

namespace {

// The values a report is built from; the first one missing or not a number is the refusal.
class ReportValues {
public:
    explicit ReportValues(std::span<const KeyValue> values) : values_(values) {}

    std::optional<std::int64_t> integer(std::string_view key) {
        std::int64_t v = 0;
        if (parseInt(text(key), v)) return v;
        fail(QT_TRANSLATE_NOOP("Refusal", "%1: expected an integer, got '%2'"), key);
        return std::nullopt;
    }
    std::optional<double> real(std::string_view key) {
        double v = 0;
        if (parseReal(text(key), v)) return v;
        fail(QT_TRANSLATE_NOOP("Refusal", "%1: expected a number, got '%2'"), key);
        return std::nullopt;
    }
    // A user-datum field: 0 while none is set (an internal datum), as the receiver reports it.
    std::optional<double> orZero(std::string_view key) {
        return text(key).empty() ? std::optional<double>(0) : real(key);
    }
    std::string_view text(std::string_view key) const {
        for (auto it = values_.rbegin(); it != values_.rend(); ++it)
            if (it->key == key) return it->value;
        return {};
    }
    Refusal why;

private:
    void fail(const char *form, std::string_view key) {
        if (why.empty()) why = refusal(form, {std::string(key), std::string(text(key))});
    }
    std::span<const KeyValue> values_;
};

template <class T, class U> std::optional<T> as(const std::optional<U> &v) {
    return v ? std::optional<T>(static_cast<T>(*v)) : std::nullopt;
}

SettingsReport message0(ReportValues &v) {
    SettingsReport m;
    m.number = 0;
    // Each message's place in the output sequence, 1-based (0: not in it).
    std::vector<std::string> order;
    for (const std::string &id : sequenceIds(v.text("output.sequence")))
        if (std::find(kNmeaMessageIds.begin(), kNmeaMessageIds.end(), id) !=
                    kNmeaMessageIds.end() &&
            std::find(order.begin(), order.end(), id) == order.end())
            order.push_back(id);
    for (std::size_t i = 0; i < kNmeaMessageIds.size(); ++i) {
        const auto at = std::find(order.begin(), order.end(), kNmeaMessageIds[i]);
        m.sequence[i] = at == order.end() ? 0 : static_cast<int>(at - order.begin() + 1);
        m.delay[i] = as<int>(v.integer("rate." + std::string(kNmeaMessageIds[i])));
    }
    int modes[5] = {};
    for (std::size_t i = 0; i < kNavDataMessageIds.size(); ++i)
        modes[i] = static_cast<int>(
                v.integer("nmrx." + std::string(kNavDataMessageIds[i])).value_or(0));
    m.nmrxEnabled = nmrxEnabledWord(modes);
    const auto baud = v.integer("serial.baud"), parity = v.integer("serial.parity"),
               protocol = v.integer("serial.protocol");
    if (baud && parity && protocol)
        m.uartSettings = uartSettingsWord(static_cast<int>(*baud), static_cast<int>(*parity),
                                          static_cast<int>(*protocol));
    return m;
}

SettingsReport message1(ReportValues &v, const SettingsReportState &state) {
    SettingsReport m;
    m.number = 1;
    m.iono = state.iono;
    m.ionoValid = state.ionoValid ? 1 : 0;
    m.numBlocks = state.numBlocks;
    const std::string_view tz = v.text("fix.timeZone");
    if (const auto minutes = parseTimeZone(tz)) {
        m.tzHours = *minutes / 60;
        m.tzMinutes = *minutes % 60;
    } else if (v.why.empty()) {
        v.why = refusal(QT_TRANSLATE_NOOP("Refusal", "fix.timeZone: '%1' is not accepted; "
                                                     "accepted: h:m with hours -13..13 and "
                                                     "minutes 0..59"),
                        {std::string(tz)});
    }
    return m;
}

SettingsReport message2(ReportValues &v, const SettingsReportState &state) {
    SettingsReport m;
    m.number = 2;
    m.maxPdop = v.real("fix.maxPdop");
    m.maxHdop = v.real("fix.maxHdop");
    m.invalidSv = state.invalidSv;
    m.minCno = v.real("fix.minSnr");
    m.minElevation = v.real("fix.minElevation");
    m.maxTm = as<int>(v.integer("nav.channels"));
    m.maxSvForFix = state.maxSvForFix;
    return m;
}

SettingsReport message3(ReportValues &v, const SettingsReportState &state) {
    SettingsReport m;
    m.number = 3;
    m.acqThreshold1 = state.acqThreshold1;
    m.acqThreshold2 = state.acqThreshold2;
    m.noiseFloor = v.integer("fix.noiseFloor");
    m.kalmanMode = state.kalmanMode;
    m.defaultAltitude = v.integer("fix.altitude2d");
    return m;
}

SettingsReport message4(ReportValues &v) {
    SettingsReport m;
    m.number = 4;
    m.correction = as<int>(v.integer("datum.correction"));
    m.datum = as<int>(v.integer("datum.mapDatum"));
    const bool user = m.datum == 500;
    auto field = [&](const char *key) { return user ? v.orZero(key) : std::optional<double>(0); };
    m.dx = as<std::int64_t>(field("datum.dx"));
    m.dy = as<std::int64_t>(field("datum.dy"));
    m.dz = as<std::int64_t>(field("datum.dz"));
    const auto iflat = field("datum.inverseFlattening"), a = field("datum.semiMajorAxis");
    if (iflat) m.iflatRaw = *iflat == 0 ? 0 : std::llround((*iflat - 290.0) * 1e6);
    if (a) m.majorARaw = *a == 0 ? 0 : std::llround((*a - 6370000.0) * 1000.0);
    return m;
}

} // namespace

EncodeResult encodeSettingsReports(std::span<const KeyValue> values,
                                   const SettingsReportState &state, std::string_view prefix) {
    ReportValues v(values);
    const SettingsReport messages[] = {message0(v), message1(v, state), message2(v, state),
                                       message3(v, state), message4(v)};
    EncodeResult out;
    if (!v.why.empty()) {
        out.refuse(std::move(v.why));
        return out;
    }
    for (const SettingsReport &m : messages) {
        EncodeResult one = encodeSettingsReport(m, prefix);
        if (!one.ok()) return one;
        out.sentences.push_back(std::move(one.sentences.front()));
    }
    return out;
}

} // namespace gnss::nemerix
