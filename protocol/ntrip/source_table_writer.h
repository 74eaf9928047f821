#pragma once
// The caster's side of source tables: STR records written from a StreamEntry (the fields
// source_table.h reads back), and the whole table ended by ENDSOURCETABLE.
//
//   STR;BASE;Moscow;RTCM 3.3;1005(10),1077(1);2;GPS+GLO;LOCAL;RUS;55.75;37.62;0;0;
//       GNSS Workbench;none;B;N;9600;
//
// A field never breaks the record: ';' becomes ',' (but in misc, the last field, which may hold
// them), line ends and other control characters are dropped. Latitude and longitude are written
// with two decimals (as casters do); an unset number is an empty field. Lines end in CR LF.
#include "ntrip/source_table.h"

#include <span>
#include <string>

namespace gnss::ntrip {

// One STR line with its CR LF.
std::string streamRecord(const StreamEntry &e);
// The STR lines of `streams`, then "ENDSOURCETABLE\r\n".
std::string writeSourceTable(std::span<const StreamEntry> streams);

} // namespace gnss::ntrip
