// 4.14 PNVGRTK: RTK engine parameters (command and reply). Any mix of parameters of Table 4: a
// parameter followed by its value(s) is set, one without a value is queried; the reply carries
// every parameter named in the request with its value(s).
//
//   $PNVGRTK,ccc[,x[,x,x]][,ccc[,x...]]...*hh
//   $PNVGRTK,MODE,1,BASEXYZ,4268995.2112,721584.9731,4668481.3737*1D
//   $PNVGRTK,BASEBLH,0.8263954319,0.1674465031,467.7040*04
//   $PNVGRTK,BASEXYZ*hh   (query)
#include "nvs/nvs_encode_util.h"

#include "core/field_parse.h"
#include "core/wgs84.h"

#include <cmath>

namespace gnss::nvs {

namespace {

constexpr std::string_view kNames[] = {
        "MODE",     "PVTRATE",   "SYSGPS",    "SYSGLO",   "SYSSBAS",    "ELGPS",   "ELGLO",
        "ELSBAS",   "ELMASKA",   "SNR",       "SNRMASKA", "RTCMAGE",    "BASEID",  "RTCMRATE",
        "BASEXYZ",  "BASEBLH",   "BASETH",    "BASENMEA", "AVGTIME",    "AVGMODE", "RAIM",
        "SFMODE",   "SFTRS",     "DPFMODE",   "VRSMODE",  "ICBGLO",     "ICBMODE", "ICBTIME",
        "ICBMBGLO", "ICBMBMODE", "ICBMBTIME", "BASELINE", "INITGPSWEEK"};
static_assert(std::size(kNames) == 33, "Table 4 has 33 parameters");

// A field that starts a parameter: a Table 4 name, or (for parameters of later firmware) a word
// of at least two upper-case letters/digits starting with a letter. Single letters (N, S, E, W
// of the NMEA form of BASEBLH) and numbers are values.
bool isNameToken(std::string_view t) {
    if (isRtkParameter(t)) return true;
    if (t.size() < 2 || t.front() < 'A' || t.front() > 'Z') return false;
    for (char c : t)
        if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) return false;
    return true;
}

std::vector<std::string_view> splitCommas(std::string_view v) {
    std::vector<std::string_view> out;
    while (true) {
        const auto comma = v.find(',');
        out.push_back(v.substr(0, comma));
        if (comma == std::string_view::npos) break;
        v.remove_prefix(comma + 1);
    }
    return out;
}

std::string validateBaseBlh(std::string_view value) {
    const auto parts = splitCommas(value);
    double b, l, h;
    if (parts.size() == 3 && parseReal(parts[0], b) && parseReal(parts[1], l) &&
        parseReal(parts[2], h)) {
        using wgs84::kPi;
        if (std::fabs(b) > kPi / 2)
            return "rtk.BASEBLH: latitude B " + std::string(parts[0]) +
                   " rad is out of range; accepted: -1.5708..1.5708 rad";
        if (l < -kPi || l > 2 * kPi)
            return "rtk.BASEBLH: longitude L " + std::string(parts[1]) +
                   " rad is out of range; accepted: -3.1416..6.2832 rad";
        return {};
    }
    double lat, lon;
    if (parts.size() == 5 && parseDegreesMinutes(parts[0], 90, lat) &&
        (parts[1] == "N" || parts[1] == "S") && parseDegreesMinutes(parts[2], 180, lon) &&
        (parts[3] == "E" || parts[3] == "W") && parseReal(parts[4], h))
        return {};
    return "rtk.BASEBLH: expected B,L,H (radians, radians, metres) or the NMEA form "
           "ddmm.mmmm,N|S,dddmm.mmmm,E|W,H; got '" +
           std::string(value) + "'";
}

std::string validateBaseXyz(std::string_view value) {
    const auto parts = splitCommas(value);
    double v;
    bool ok = parts.size() == 3;
    for (auto p : parts) ok = ok && parseReal(p, v);
    if (ok) return {};
    return "rtk.BASEXYZ: expected three numbers X,Y,Z in metres (ECEF); got '" +
           std::string(value) + "'";
}

} // namespace

const MessageType Rtk::kType{"PNVGRTK"};

std::span<const std::string_view> rtkParameterNames() {
    return kNames;
}

bool isRtkParameter(std::string_view name) {
    for (auto n : kNames)
        if (n == name) return true;
    return false;
}

Refusal validateRtkValue(std::string_view name, std::string_view value) {
    if (!isRtkParameter(name))
        return refusal(QT_TRANSLATE_NOOP("Refusal", "PNVGRTK: unknown parameter '%1' (Table 4: "
                                                    "MODE, PVTRATE, ... INITGPSWEEK)"),
                       {std::string(name)});
    if (value.empty())
        return refusal(QT_TRANSLATE_NOOP("Refusal", "rtk.%1: a value is required (an empty value "
                                                    "is a query)"),
                       {std::string(name)});
    if (name == "BASEXYZ") return validateBaseXyz(value);
    if (name == "BASEBLH") return validateBaseBlh(value);
    return checkSetting("rtk." + std::string(name), value);
}

const RtkParam *Rtk::find(std::string_view name) const {
    for (const auto &p : params)
        if (p.name == name) return &p;
    return nullptr;
}

bool decodeRtk(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<Rtk>(s, ctx, 1, [&](FieldReader &r, Rtk &m) {
        for (std::size_t i = 0; i < s.fieldCount(); ++i) {
            const auto t = r.text(i);
            if (t.empty()) continue; // "MODE,,PVTRATE": an empty value is no value
            if (isNameToken(t)) {
                m.params.push_back({t, {}});
            } else if (m.params.empty()) {
                r.fail(i, "parameter",
                       QT_TRANSLATE_NOOP("Refusal", "a value before any parameter name"));
                break;
            } else {
                m.params.back().values.push_back(t);
            }
        }
        if (r.ok() && m.params.empty())
            r.failSentence(std::string(QT_TRANSLATE_NOOP("Refusal", "PNVGRTK names no parameter")));
    });
}

void Rtk::writeJson(JsonWriter &w) const {
    w.beginObject().key("params").beginObject();
    for (const auto &p : params) {
        w.key(p.name);
        if (p.values.empty()) {
            w.null();
        } else if (p.values.size() == 1) {
            writeValue(w, p.values.front());
        } else {
            w.beginArray();
            for (auto v : p.values) writeValue(w, v);
            w.endArray();
        }
    }
    w.endObject().endObject();
}

EncodeResult encodeRtk(std::span<const RtkSet> set, std::span<const std::string> query) {
    if (set.empty() && query.empty())
        return refuse(std::string("PNVGRTK: name at least one parameter to set or query"));
    std::string body = "PNVGRTK";
    for (const auto &p : set) {
        if (auto err = validateRtkValue(p.name, p.value); !err.empty()) return refuse(err);
        body += "," + p.name + "," + p.value;
    }
    for (const auto &q : query) {
        if (!isRtkParameter(q))
            return refuse("PNVGRTK: unknown parameter '" + q +
                          "' (Table 4: MODE, PVTRATE, ... INITGPSWEEK)");
        body += "," + q;
    }
    return built(body);
}

} // namespace gnss::nvs
