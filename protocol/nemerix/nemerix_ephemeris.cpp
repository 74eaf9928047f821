// PNMRX301: ephemeris, three messages per satellite (the contents of subframes 1, 2, 3).
//
//   $PNMRX301,sv,1,wn,hl,u,tgd,iodc,toc,af2,af1,af0*hh
//   $PNMRX301,sv,2,iode,crs,dn,m0,cuc,e,cus,sqrta,toe*hh
//   $PNMRX301,sv,3,cic,om0,cis,i0,crc,w,omd,iode,idot*hh
//
// Widths, signs and scales are those of IS-GPS-200 (20.3.3.3 and 20.3.3.4, tables 20-I and
// 20-III). The spec's tables disagree with it in these places, and IS-GPS-200 wins
// (docs/spec-notes.md):
//   - Subframe 1: toc scale is 2^4 s (table: 2^-4); af2 scale is 2^-55 s/s^2 (table: 2^-31).
//   - Subframe 2: the second "Cuc" is Cus; e is 32-bit UNSIGNED (table: signed); sqrt(A) is
//     32-bit UNSIGNED in m^1/2 (table: signed, "Meters^1/4").
//   - Subframe 3: i0 is a 32-bit value (table prints width 4).
// Every message stands alone here; EphemerisAssembler (nemerix_ephemeris.h) joins the three.
// encodeEphemerisSubframe writes one message as the receiver sends it (each word in its
// field's width: "$PNMRX301,5,1,3FC,00,0,00,0A4,0E10,00,0000,000000*hh").
#include "nemerix/nemerix_ephemeris.h"
#include "core/decode_with.h"
#include "nemerix/nemerix_commands.h"
#include "nemerix/nemerix_fields.h"

namespace gnss::nemerix {

const MessageType EphemerisSubframe::kType{"PNMRX301"};
const MessageType Ephemeris::kType{"PNMRX301 ephemeris"};

namespace {
constexpr HexFieldDef kSf1[] = {
        {"week", 10, false, 0, "weeks"}, {"health", 6, false, 0, ""},   {"ura", 4, false, 0, ""},
        {"tgd", 8, true, -31, "s"},      {"iodc", 10, false, 0, ""},    {"toc", 16, false, 4, "s"},
        {"af2", 8, true, -55, "s/s^2"},  {"af1", 16, true, -43, "s/s"}, {"af0", 22, true, -31, "s"},
};
constexpr HexFieldDef kSf2[] = {
        {"iode", 8, false, 0, ""},
        {"crs", 16, true, -5, "m"},
        {"delta_n", 16, true, -43, "semicircles/s"},
        {"m0", 32, true, -31, "semicircles"},
        {"cuc", 16, true, -29, "rad"},
        {"e", 32, false, -33, ""},
        {"cus", 16, true, -29, "rad"},
        {"sqrt_a", 32, false, -19, "m^1/2"},
        {"toe", 16, false, 4, "s"},
};
constexpr HexFieldDef kSf3[] = {
        {"cic", 16, true, -29, "rad"},
        {"omega0", 32, true, -31, "semicircles"},
        {"cis", 16, true, -29, "rad"},
        {"i0", 32, true, -31, "semicircles"},
        {"crc", 16, true, -5, "m"},
        {"omega", 32, true, -31, "semicircles"},
        {"omega_dot", 24, true, -43, "semicircles/s"},
        {"iode", 8, false, 0, ""},
        {"idot", 14, true, -43, "semicircles/s"},
};

// Nominal URA in metres by index (IS-GPS-200 20.3.3.3.1.3); index 15: no accuracy prediction.
constexpr double kUra[] = {2.4,  3.4,   4.85,  6.85,  9.65,   13.65,  24.0,  48.0,
                           96.0, 192.0, 384.0, 768.0, 1536.0, 3072.0, 6144.0};
} // namespace

std::span<const HexFieldDef> EphemerisSubframe::fields(int subframe) {
    switch (subframe) {
    case 1: return kSf1;
    case 2: return kSf2;
    case 3: return kSf3;
    default: return {};
    }
}

std::optional<double> EphemerisSubframe::value(int field) const {
    if (field < 0) return std::nullopt;
    return valueOf(fields(subframe), raw, static_cast<std::size_t>(field));
}

Refusal EphemerisSubframe::setValue(int field, double v) {
    const auto defs = fields(subframe);
    if (field < 0 || static_cast<std::size_t>(field) >= defs.size())
        return refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                       {"field", std::to_string(field),
                        defs.empty() ? std::string("none (subframe 1..3 first)")
                                     : "0.." + std::to_string(defs.size() - 1)});
    return setValueOf(defs, raw, static_cast<std::size_t>(field), v);
}

bool decodeEphemeris(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<EphemerisSubframe>(s, ctx, 2, [](FieldReader &r, EphemerisSubframe &m) {
        const auto sv = r.integer(0, "SV id");
        const auto sf = r.integer(1, "subframe");
        if (sv && (*sv < 1 || *sv > 32))
            r.fail(0, "SV id", QT_TRANSLATE_NOOP("Refusal", "out of range 1..32"));
        if (sf && (*sf < 1 || *sf > 3))
            r.fail(1, "subframe", QT_TRANSLATE_NOOP("Refusal", "not 1, 2 or 3"));
        if ((!sv || !sf) && r.ok())
            r.failSentence(
                    std::string(QT_TRANSLATE_NOOP("Refusal", "SV id and subframe are required")));
        if (r.ok()) {
            m.sv = *sv;
            m.subframe = *sf;
            const auto defs = EphemerisSubframe::fields(m.subframe);
            const std::size_t n = usedFields(r);
            if (n != 2 + defs.size())
                r.failSentence(refusal(QT_TRANSLATE_NOOP("Refusal", "subframe %1: expected %2 "
                                                                    "hex fields, got %3"),
                                       {std::to_string(m.subframe), std::to_string(defs.size()),
                                        std::to_string(n - 2)}));
            for (std::size_t f = 0; f < defs.size() && r.ok(); ++f) {
                m.raw[f] = readHex(r, 2 + f, defs[f]);
                if (!m.raw[f] && r.ok())
                    r.fail(2 + f, defs[f].key.data(), QT_TRANSLATE_NOOP("Refusal", "missing"));
            }
        }
    });
}

namespace {
void writeUra(JsonWriter &w, const std::optional<std::int64_t> &ura) {
    w.key("ura_m");
    if (ura && *ura >= 0 && *ura < 15)
        w.value(kUra[*ura]);
    else
        w.null();
}
} // namespace

void EphemerisSubframe::writeJson(JsonWriter &w) const {
    w.beginObject().field("sv", sv).field("subframe", subframe);
    writeHexFields(w, fields(subframe), raw);
    if (subframe == 1) writeUra(w, raw[Ura]);
    w.endObject();
}

EncodeResult encodeEphemerisSubframe(const EphemerisSubframe &m, std::string_view prefix) {
    EncodeResult r;
    if (m.sv < 1 || m.sv > 32) {
        r.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                         {"sv", std::to_string(m.sv), "1..32"}));
        return r;
    }
    const auto defs = EphemerisSubframe::fields(m.subframe);
    if (defs.empty()) {
        r.refuse(refusal(QT_TRANSLATE_NOOP("Refusal", "%1: %2 is out of range; accepted: %3"),
                         {"subframe", std::to_string(m.subframe), "1..3"}));
        return r;
    }
    for (std::size_t f = 0; f < defs.size(); ++f)
        if (Refusal why = checkRaw(m.raw[f], defs[f]); !why.empty()) {
            r.refuse(std::move(why));
            return r;
        }
    return buildCommand("301",
                        "," + std::to_string(m.sv) + "," + std::to_string(m.subframe) +
                                hexFields(defs, std::span(m.raw).first(defs.size())),
                        prefix);
}

// ---- Assembly -------------------------------------------------------------------------------

bool Ephemeris::consistent() const {
    const auto iodc = sf1[EphemerisSubframe::Iodc];
    const auto iode2 = sf2[EphemerisSubframe::Iode2];
    const auto iode3 = sf3[EphemerisSubframe::Iode3];
    return iodc && iode2 && iode3 && *iode2 == *iode3 && (*iodc & 0xFF) == *iode2;
}

double Ephemeris::value(int subframe, int field) const {
    const auto &a = subframe == 1 ? sf1 : subframe == 2 ? sf2 : sf3;
    const auto defs = EphemerisSubframe::fields(subframe);
    return a[field] ? scaled(*a[field], defs[field]) : 0.0;
}

void Ephemeris::writeJson(JsonWriter &w) const {
    w.beginObject().field("sv", sv).field("consistent", consistent());
    writeHexFields(w, kSf1, sf1);
    writeUra(w, sf1[EphemerisSubframe::Ura]);
    // Subframe 3's IODE repeats subframe 2's: written once as "iode", the other as "iode3".
    writeHexFields(w, kSf2, sf2);
    for (std::size_t f = 0; f < std::size(kSf3); ++f) {
        if (f == EphemerisSubframe::Iode3) {
            HexFieldDef d = kSf3[f];
            d.key = "iode3";
            writeHexField(w, d, sf3[f]);
        } else {
            writeHexField(w, kSf3[f], sf3[f]);
        }
    }
    w.endObject();
}

std::optional<Ephemeris> EphemerisAssembler::add(const EphemerisSubframe &part) {
    if (part.sv < 1 || part.sv > 32 || part.subframe < 1 || part.subframe > 3) return std::nullopt;
    Pending &p = pending_[static_cast<std::size_t>(part.sv - 1)];
    p.eph.sv = part.sv;
    auto &dst = part.subframe == 1 ? p.eph.sf1 : part.subframe == 2 ? p.eph.sf2 : p.eph.sf3;
    dst = part.raw;
    p.have |= 1u << (part.subframe - 1);
    if (p.have != 7u) return std::nullopt;
    // Complete only when the issue of data matches across the three (IODE = IODC low 8 bits):
    // a stale subframe from a previous upload is kept waiting for its fresh partner.
    if (!p.eph.consistent()) return std::nullopt;
    Ephemeris done = p.eph;
    p = Pending{};
    return done;
}

void EphemerisAssembler::reset() {
    pending_ = {};
}

int EphemerisAssembler::pendingMask(int sv) const {
    if (sv < 1 || sv > 32) return 0;
    return static_cast<int>(pending_[static_cast<std::size_t>(sv - 1)].have);
}

} // namespace gnss::nemerix
