// 4.22 PNVGDOP: dilutions of precision of the calculated position. (The spec's field table
// names the address PNVGSDH, a copy-paste typo: the example shows PNVGDOP. docs/spec-notes.md.)
//
//   $PNVGDOP,hhmmss.ss,x.x,x.x,x.x,x.x,x.x,x.x,x.x,a*hh
//            0 time, 1 GDOP, 2 PDOP, 3 HDOP, 4 VDOP, 5 TDOP, 6 nDOP, 7 eDOP, 8 mode
#include "nvs/nvs_encoders.h"
#include "nvs/nvs_output_fields.h"

namespace gnss::nvs {

const MessageType Dop::kType{"PNVGDOP"};

// Each DOP with two decimals.
const FieldRow<Dop> Dop::kFields[] = {
        {&Dop::time, "time", "time"},
        {&Dop::gdop, "GDOP", "gdop", {2, 0, kMaxDop}},
        {&Dop::pdop, "PDOP", "pdop", {2, 0, kMaxDop}},
        {&Dop::hdop, "HDOP", "hdop", {2, 0, kMaxDop}},
        {&Dop::vdop, "VDOP", "vdop", {2, 0, kMaxDop}},
        {&Dop::tdop, "TDOP", "tdop", {2, 0, kMaxDop}},
        {&Dop::ndop, "nDOP", "ndop", {2, 0, kMaxDop}},
        {&Dop::edop, "eDOP", "edop", {2, 0, kMaxDop}},
        {&Dop::mode, "mode", "mode"},
};

EncodeResult encodeDop(const Dop &m) {
    return encodeRows(m, Dop::kFields);
}

} // namespace gnss::nvs
