#pragma once
// GeoS-5 proprietary messages ($GPSGG,<name>,...) and the Galileo return link message RLM.
// Field diagrams live above each decoder (geostar_rquery.cpp, geostar_nquery.cpp, ...).
#include "core/dialect.h"
#include "core/field_types.h"
#include "core/message.h"
#include "geostar/geostar_commands.h"
#include "geostar/geostar_status_words.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace gnss::geostar {

// $GPSGG,RQUERY,GEOS-5,V.x.xxx,ddmmyy,status,config1,config2 (section 3.11).
struct Rquery : Message {
    static const MessageType kType;
    Rquery() : Message(kType) {}
    std::string_view receiverName;    // "GEOS-5" for every module of the family
    std::string_view firmware;        // as printed: "V.5.102"
    std::string_view firmwareVersion; // without the "V." prefix: "5.102"
    std::optional<Date> firmwareDate; // ddmmyy
    StatusWord status;                // table 7
    ConfigRegister1 config1;          // table 8
    ConfigRegister2 config2;          // table 9
    void writeJson(JsonWriter &w) const override;
};

// $GPSGG,NQUERY,port,rate,version,<ten per-message rate codes> (section 3.12; the order of the
// per-message codes is inferred from the single example: docs/spec-notes.md, "NQUERY field order").
struct Nquery : Message {
    static const MessageType kType;
    static constexpr std::size_t kMessages = 10;
    // Names in field order; the 7th position is not known (probably GNS or reserved).
    static constexpr std::array<std::string_view, kMessages> kNames = {
            "GGA", "GLL", "GSA", "GSV", "RMC", "VTG", "", "ZDA", "DTM", "RLM"};
    Nquery() : Message(kType) {}
    std::optional<int> port;        // 0 or 1
    std::optional<int> rateCode;    // 0 10 Hz, 1 5 Hz, 2 2 Hz, 3 1 Hz
    std::optional<int> nmeaVersion; // 2 (v2.x) or 4 (v4.10)
    // Per-message code: '0' off, '1' every second, '2' every 2 s, '3' every 20 s, 'R' at the
    // output rate; '\0' when the field is absent.
    std::array<char, kMessages> codes{};
    std::size_t codeCount = 0;
    void writeJson(JsonWriter &w) const override;
};

// Meaning of an NQUERY per-message code: "off", "1 s", "2 s", "20 s", "output rate", "unknown".
std::string_view nqueryCodeMeaning(char code);

// $GPSGG,JAMDET, (section 3.13): the receiver detected jamming.
struct Jamdet : Message {
    static const MessageType kType;
    Jamdet() : Message(kType) {}
    void writeJson(JsonWriter &w) const override;
};

// Any input command of section 4 ($GPSGG,CSTART, $GPSGG,BDR115, ...), decoded so the console
// shows what was sent and the simulator reads what it receives.
struct Command : Message {
    static const MessageType kType;
    Command() : Message(kType) {}
    const CommandDef *def = nullptr;
    void writeJson(JsonWriter &w) const override;
};

// $GPRLM,beacon,hhmmss.ss,code,parameters (section 3.10): Galileo return link message.
struct Rlm : Message {
    static const MessageType kType;
    Rlm() : Message(kType) {}
    std::string_view beaconId; // 15 hex characters (COSPAS-SARSAT beacon)
    std::optional<TimeOfDay> time;
    std::optional<int> messageCode;       // 0-15 (one hex digit)
    std::string_view parameters;          // 4 hex (short message) or 24 hex (long message)
    std::string_view serviceName() const; // from the message code
    void writeJson(JsonWriter &w) const override;
};

// $GPSGG,<first field>,...: dispatches on the first field (replies, JAMDET, commands).
bool decodeSgg(const Sentence &, DecodeContext &);
bool decodeRquery(const Sentence &, DecodeContext &);
bool decodeNquery(const Sentence &, DecodeContext &);
bool decodeJamdet(const Sentence &, DecodeContext &);
bool decodeCommand(const Sentence &, DecodeContext &);
bool decodeRlm(const Sentence &, DecodeContext &);

} // namespace gnss::geostar
