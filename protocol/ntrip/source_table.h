#pragma once
// An NTRIP source table: what a caster offers (STR: streams, CAS: casters, NET: networks),
// ended by ENDSOURCETABLE. Fields are separated by ';'; the last (misc) may itself hold ';'.
//
//   STR;mountpoint;identifier;format;format-details;carrier;nav-system;network;country;
//       latitude;longitude;nmea;solution;generator;compr-encryp;authentication;fee;bitrate;misc
//   CAS;host;port;identifier;operator;nmea;country;latitude;longitude;fallback host;
//       fallback port;misc
//   NET;identifier;operator;authentication;fee;web-net;web-str;web-reg;misc
//
// Tolerant: a record with fewer fields than the standard keeps what it has (counted as short);
// a field that does not read as its type is left unset; lines that are no record at all are
// counted and skipped. Nothing throws.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace gnss::ntrip {

struct StreamEntry {
    std::string mountpoint;
    std::string identifier;     // usually the place
    std::string format;         // "RTCM 3.2", "RTCM 3", "CMRx", "RAW" ...
    std::string formatDetails;  // messages and rates: "1005(10),1074(1),1084(1)"
    std::optional<int> carrier; // 0 none, 1 L1, 2 L1+L2
    std::string navSystem;      // "GPS+GLO+GAL"
    std::string network;
    std::string country;             // ISO 3166 alpha-3
    std::optional<double> latitude;  // degrees
    std::optional<double> longitude; // degrees
    bool wantsGga = false;           // nmea = 1: the caster needs the rover's GGA
    std::optional<int> solution;     // 0 single base, 1 network
    std::string generator;
    std::string compression;
    std::string authentication; // "N" none, "B" basic, "D" digest
    bool fee = false;           // "Y"
    std::optional<int> bitrate; // bits per second
    std::string misc;
};

struct CasterEntry {
    std::string host;
    std::optional<int> port;
    std::string identifier;
    std::string casterOperator;
    bool nmea = false;
    std::string country;
    std::optional<double> latitude, longitude;
    std::string fallbackHost;
    std::optional<int> fallbackPort;
    std::string misc;
};

struct NetworkEntry {
    std::string identifier;
    std::string networkOperator;
    std::string authentication;
    bool fee = false;
    std::string webNet, webStr, webReg;
    std::string misc;
};

// One field of a record after its tag, in the record's order: its name (snake case, as gnss-cli
// prints it) and the member it is read into.
template <class Entry> struct RecordField {
    const char *name;
    std::variant<std::string Entry::*, std::optional<int> Entry::*, std::optional<double> Entry::*,
                 bool Entry::*>
            member;
};
std::span<const RecordField<StreamEntry>> streamFields();   // STR
std::span<const RecordField<CasterEntry>> casterFields();   // CAS
std::span<const RecordField<NetworkEntry>> networkFields(); // NET

struct SourceTable {
    std::vector<StreamEntry> streams;
    std::vector<CasterEntry> casters;
    std::vector<NetworkEntry> networks;
    bool complete = false;          // ENDSOURCETABLE seen
    std::uint32_t shortRecords = 0; // STR/CAS/NET with fewer fields than the standard's
    std::uint32_t badLines = 0;     // not a record, not blank (or a record without a name)
    std::uint32_t longLines = 0;    // over kMaxLine bytes: dropped

    const StreamEntry *find(std::string_view mountpoint) const;
};

class SourceTableParser {
public:
    static constexpr std::size_t kMaxLine = 4096;
    static constexpr std::size_t kMaxRecords = 100000; // beyond this, records are counted bad

    // Any chunking; lines end with LF (CR LF or bare LF).
    void feed(std::string_view bytes);
    // The stream ended: a last line without LF is read too.
    void finish();
    bool complete() const { return table_.complete; }
    const SourceTable &table() const { return table_; }
    SourceTable take() { return std::move(table_); }

private:
    void line(std::string_view l);

    SourceTable table_;
    std::string line_;
    bool overlong_ = false;
};

// The whole text at once.
SourceTable parseSourceTable(std::string_view text);

// Does this format name an RTCM 3 stream ("RTCM 3", "RTCM 3.2", "RTCM3.3", "rtcm 3.1")?
bool isRtcm3Format(std::string_view format);

} // namespace gnss::ntrip
