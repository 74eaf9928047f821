#pragma once
// Standard NMEA-0183 (2.x - 4.11) messages as small typed structs. Empty fields are
// std::nullopt. Each struct's decoder and field diagram live in <type>.cpp; a sentence that is a
// plain list of fields is a FieldMessage (core/field_table.h), its rows there decode it and
// write its JSON.
#include "core/decode_with.h"
#include "core/dialect.h"
#include "core/field_reader.h"
#include "core/field_table.h"
#include "core/field_types.h"
#include "core/finish_decode.h"
#include "core/message.h"
#include "core/satellite.h"
#include "core/slot_array.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gnss::nmea {

// The GGA field layout, shared with vendor sentences that repeat it (NVS PNVGTMC).
struct GgaFields {
    std::optional<TimeOfDay> time;
    std::optional<double> lat, lon; // signed decimal degrees
    std::optional<int> quality;     // 0 none, 1 GPS, 2 DGPS, 4 RTK fixed, 5 float, 6 DR, ...
    std::optional<int> satsUsed;
    std::optional<double> hdop;
    std::optional<double> altMsl;   // metres above mean sea level
    std::optional<double> geoidSep; // metres, geoid above ellipsoid
    std::optional<double> dgpsAge;  // seconds
    std::optional<int> dgpsStation;
};
// Reads fields 0-13 in the GGA layout (after require(6) has passed).
void readGgaFields(FieldReader &r, GgaFields &f);
void writeGgaFieldsJson(JsonWriter &w, const GgaFields &f);

struct Gga : Message, GgaFields {
    static const MessageType kType;
    Gga() : Message(kType) {}
    void writeJson(JsonWriter &w) const override { writeGgaFieldsJson(w, *this); }
};

struct Gll : FieldMessage<Gll> {
    static const MessageType kType;
    static const FieldRow<Gll> kFields[5];
    static constexpr std::size_t kRequired = 4;
    std::optional<double> lat, lon;
    std::optional<TimeOfDay> time;
    std::optional<char> status; // A valid, V invalid
    std::optional<char> mode;   // 2.3+: A D E M N (GeoStar also G, M)
};

struct Gns : Message {
    static const MessageType kType;
    Gns() : Message(kType) {}
    std::optional<TimeOfDay> time;
    std::optional<double> lat, lon;
    std::string_view mode; // one character per system (GPS, GLONASS, Galileo, BeiDou, ...)
    std::optional<int> satsUsed;
    std::optional<double> hdop, altMsl, geoidSep, dgpsAge;
    std::optional<int> dgpsStation;
    std::optional<char> navStatus; // 4.10+: S safe, C caution, U unsafe, V not valid
    void writeJson(JsonWriter &w) const override;
};

struct Gsa : Message {
    static const MessageType kType;
    static constexpr std::size_t kMaxIds = 32;
    Gsa() : Message(kType) {}
    std::optional<char> mode;    // M manual, A automatic
    std::optional<int> fix;      // 1 none, 2 2D, 3 3D
    SlotArray<int, kMaxIds> ids; // the first idCount are set
    std::size_t idCount = 0;
    SlotArray<SatelliteRef, kMaxIds> satellites; // ids mapped to constellation + PRN
    std::optional<double> pdop, hdop, vdop;
    std::optional<int> systemId;                   // 4.10+
    Constellation system = Constellation::Unknown; // from the system id or the talker
    void writeJson(JsonWriter &w) const override;
};

struct GsvSatellite {
    int id = 0; // as printed
    SatelliteRef sat;
    std::optional<int> elevation; // degrees, may be negative (GeoStar: -2 = position unknown)
    std::optional<int> azimuth;   // degrees true
    std::optional<int> snr;       // dB-Hz
};

struct Gsv : Message {
    static const MessageType kType;
    static constexpr std::size_t kMaxSatellites = 16;
    Gsv() : Message(kType) {}
    std::optional<int> total, index, inView;
    std::optional<int> signalId;                        // 4.10+
    Constellation system = Constellation::Unknown;      // from the talker (Unknown for GN)
    SlotArray<GsvSatellite, kMaxSatellites> satellites; // the first satelliteCount are set
    std::size_t satelliteCount = 0;
    void writeJson(JsonWriter &w) const override;
};

struct Rmc : Message {
    static const MessageType kType;
    Rmc() : Message(kType) {}
    std::optional<TimeOfDay> time;
    std::optional<char> status; // A valid, V warning
    std::optional<double> lat, lon;
    std::optional<double> sogKnots, cog;
    std::optional<Date> date;
    std::optional<double> magVar; // degrees, east positive
    std::optional<char> mode;
    std::optional<char> navStatus;
    void writeJson(JsonWriter &w) const override;
};

struct Vtg : Message {
    static const MessageType kType;
    Vtg() : Message(kType) {}
    std::optional<double> cogTrue, cogMagnetic, sogKnots, sogKmh;
    std::optional<char> mode;
    void writeJson(JsonWriter &w) const override;
};

struct Zda : Message {
    static const MessageType kType;
    Zda() : Message(kType) {}
    std::optional<TimeOfDay> time;
    std::optional<Date> date;
    std::optional<int> tzHours, tzMinutes;
    void writeJson(JsonWriter &w) const override;
};

struct Hdt : Message {
    static const MessageType kType;
    Hdt() : Message(kType) {}
    std::optional<double> heading; // degrees true
    void writeJson(JsonWriter &w) const override;
};

struct Dtm : Message {
    static const MessageType kType;
    Dtm() : Message(kType) {}
    std::string_view datum, subdivision, referenceDatum;
    std::optional<double> latOffset, lonOffset; // minutes, signed (N/E positive)
    std::optional<double> altOffset;            // metres
    void writeJson(JsonWriter &w) const override;
};

struct Gst : FieldMessage<Gst> {
    static const MessageType kType;
    static const FieldRow<Gst> kFields[8];
    static constexpr std::size_t kRequired = 8;
    std::optional<TimeOfDay> time;
    std::optional<double> rms, sdMajor, sdMinor, orientation, sdLat, sdLon, sdAlt;
};

struct Txt : Message {
    static const MessageType kType;
    Txt() : Message(kType) {}
    std::optional<int> total, number, id;
    std::string_view text;
    void writeJson(JsonWriter &w) const override;
};

// Query: $ttllQ,ADDRESS — talker tt asks listener ll for sentence ADDRESS.
struct Query : Message {
    static const MessageType kType;
    Query() : Message(kType) {}
    std::string_view requester, listener, address;
    void writeJson(JsonWriter &w) const override;
};

bool decodeGga(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeGll = decodeMessage<Gll>;
bool decodeGns(const Sentence &, DecodeContext &);
bool decodeGsa(const Sentence &, DecodeContext &);
bool decodeGsv(const Sentence &, DecodeContext &);
bool decodeRmc(const Sentence &, DecodeContext &);
bool decodeVtg(const Sentence &, DecodeContext &);
bool decodeZda(const Sentence &, DecodeContext &);
bool decodeHdt(const Sentence &, DecodeContext &);
bool decodeDtm(const Sentence &, DecodeContext &);
inline constexpr DecodeFn decodeGst = decodeMessage<Gst>;
bool decodeTxt(const Sentence &, DecodeContext &);
bool decodeQuery(const Sentence &, DecodeContext &);

} // namespace gnss::nmea
