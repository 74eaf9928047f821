#include "compare/comparison_json.h"

#include "core/field_types.h"
#include "core/json_writer.h"

#include <cmath>
#include <cstdio>

namespace gnss::compare {

namespace {

double rounded(double v, int digits) {
    const double f = std::pow(10.0, digits);
    return std::round(v * f) / f;
}

std::string timeText(std::int64_t ms) {
    TimeOfDay t;
    t.nanos = ms * 1'000'000;
    t.decimals = 3;
    return t.toString();
}

void writeSpread(JsonWriter &w, const Spread &s, int digits) {
    w.beginObject()
            .field("mean", rounded(s.mean, digits))
            .field("median", rounded(s.median, digits))
            .field("p95", rounded(s.p95, digits))
            .field("count", static_cast<std::uint64_t>(s.count))
            .endObject();
}

void writeSatellites(JsonWriter &w, const std::vector<SatelliteRef> &sats) {
    w.beginArray();
    for (SatelliteRef s : sats) w.value(satelliteLabel(s));
    w.endArray();
}

void writeCounts(JsonWriter &w, const std::vector<SatelliteCount> &counts) {
    w.beginArray();
    for (const SatelliteCount &c : counts)
        w.beginObject()
                .field("sat", satelliteLabel(c.sat))
                .field("epochs", static_cast<std::uint64_t>(c.epochs))
                .endObject();
    w.endArray();
}

std::optional<double> metres(const std::optional<double> &v) {
    return v ? std::optional<double>(rounded(*v, 4)) : std::nullopt;
}

double share(std::size_t n, std::size_t of) {
    return of ? rounded(static_cast<double>(n) / static_cast<double>(of), 4) : 0.0;
}

} // namespace

void writeMatchJson(JsonWriter &w, const Match &m, const std::vector<std::string> &names) {
    w.beginObject().field("time", timeText(m.timeMs));
    w.key("fix").beginArray();
    for (const Observation *o : m.observations) w.value(toString(o->fix));
    w.endArray();
    w.key("differences").beginArray();
    for (std::size_t i = 0; i < m.differences.size(); ++i) {
        const Difference &d = m.differences[i];
        w.beginObject().field("receiver", i + 1 < names.size() ? names[i + 1] : std::string());
        w.field("east", metres(d.east)).field("north", metres(d.north));
        w.field("up", metres(d.up)).field("horizontal", metres(d.horizontal));
        w.key("cn0").beginArray();
        for (const SignalPair &p : d.cn0)
            w.beginObject()
                    .field("sat", satelliteLabel(p.sat))
                    .field("signal", p.signalId)
                    .field("reference", p.reference)
                    .field("other", p.other)
                    .endObject();
        w.endArray();
        w.key("only_in_reference");
        writeSatellites(w, d.onlyInReference);
        w.key("only_in_this");
        writeSatellites(w, d.onlyInOther);
        w.endObject();
    }
    w.endArray().endObject();
}

void writeReportJson(JsonWriter &w, const Report &r) {
    w.beginObject().key("receivers").beginArray();
    for (std::size_t i = 0; i < r.receivers.size(); ++i) {
        const ReceiverReport &rr = r.receivers[i];
        w.beginObject().field("name", rr.name).field("dialect", rr.dialect);
        w.field("epochs", static_cast<std::uint64_t>(rr.epochs));
        w.key("fix").beginObject();
        for (const FixCount &f : rr.fixes) w.field(toString(f.fix), share(f.epochs, rr.epochs));
        w.endObject();
        if (i > 0 && i - 1 < r.pairs.size()) {
            const PairReport &p = r.pairs[i - 1];
            w.key("difference_m").beginObject();
            w.key("east");
            writeSpread(w, p.east, 4);
            w.key("north");
            writeSpread(w, p.north, 4);
            w.key("up");
            writeSpread(w, p.up, 4);
            w.key("horizontal");
            writeSpread(w, p.horizontal, 4);
            w.field("cep50", rounded(p.cep50, 4)).field("cep95", rounded(p.cep95, 4));
            w.endObject();
            w.key("cn0_db").beginObject();
            w.field("mean", rounded(p.cn0.mean, 2)).field("median", rounded(p.cn0.median, 2));
            w.field("p95", rounded(p.cn0.p95, 2));
            w.field("signals", static_cast<std::uint64_t>(p.cn0.count));
            w.key("per_constellation").beginObject();
            for (const ConstellationCn0 &c : p.perConstellation)
                w.key(toString(c.system))
                        .beginObject()
                        .field("mean", rounded(c.difference.mean, 2))
                        .field("p95", rounded(c.difference.p95, 2))
                        .field("satellites", c.satellites)
                        .endObject();
            w.endObject().endObject();
            w.key("only_in").beginObject().key("reference");
            writeCounts(w, p.onlyInReference);
            w.key("this");
            writeCounts(w, p.onlyInThis);
            w.endObject();
        }
        w.endObject();
    }
    w.endArray().field("matched_epochs", static_cast<std::uint64_t>(r.matchedEpochs)).endObject();
}

std::string reportText(const Report &r) {
    std::string out;
    char line[512];
    std::snprintf(line, sizeof line, "%zu epochs matched on UTC time; reference: %s\n",
                  r.matchedEpochs, r.receivers.empty() ? "-" : r.receivers[0].name.c_str());
    out += line;
    for (std::size_t i = 1; i < r.receivers.size() && i - 1 < r.pairs.size(); ++i) {
        const PairReport &p = r.pairs[i - 1];
        std::snprintf(line, sizeof line,
                      "%s minus the reference: east %+.3f m, north %+.3f m, up %+.3f m (means); "
                      "horizontal CEP50 %.3f m, CEP95 %.3f m; C/N0 %+.1f dB over %zu signals\n",
                      r.receivers[i].name.c_str(), p.east.mean, p.north.mean, p.up.mean, p.cep50,
                      p.cep95, p.cn0.mean, p.cn0.count);
        out += line;
        for (const ConstellationCn0 &c : p.perConstellation) {
            std::snprintf(line, sizeof line, "  %s: C/N0 %+.1f dB (p95 %+.1f) on %d satellites\n",
                          std::string(toString(c.system)).c_str(), c.difference.mean,
                          c.difference.p95, c.satellites);
            out += line;
        }
        std::string only;
        for (const SatelliteCount &c : p.onlyInReference) only += " " + satelliteLabel(c.sat);
        if (!only.empty()) out += "  only the reference tracked:" + only + "\n";
        only.clear();
        for (const SatelliteCount &c : p.onlyInThis) only += " " + satelliteLabel(c.sat);
        if (!only.empty()) out += "  only " + r.receivers[i].name + " tracked:" + only + "\n";
    }
    return out;
}

} // namespace gnss::compare
