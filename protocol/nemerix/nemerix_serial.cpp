// PNMRX100: set serial port mode.
//
//   $PNMRX100,p,bbbbbb,y*hh
//             0 protocol (0 NMEA, 1 Nemerix binary), 1 baud, 2 parity (0 none, 1 odd, 2 even)
//   $PNMRX100,0,4800,0*48   4800 bps, no parity
#include "core/baud_rates.h"
#include "core/decode_with.h"
#include "core/field_table.h"
#include "nemerix/nemerix_actions.h"
#include "nemerix/nemerix_commands.h"

#include <algorithm>

namespace gnss::nemerix {

const MessageType SerialPort::kType{"PNMRX100"};

namespace {
bool knownBaud(int b) {
    return std::ranges::find(kSupportedBauds, b) != std::end(kSupportedBauds);
}

const FieldRow<SerialPort> kFields[] = {
        {&SerialPort::protocol, "protocol", "protocol"},
        {&SerialPort::baud, "baud", "baud"},
        {&SerialPort::parity, "parity", "parity"},
};

// The values the rows' fields may take.
void checkSerialPort(FieldReader &r, const SerialPort &m) {
    if (m.protocol && (*m.protocol < 0 || *m.protocol > 1))
        r.fail(0, "protocol", QT_TRANSLATE_NOOP("Refusal", "not 0 or 1"));
    if (m.baud && !knownBaud(*m.baud))
        r.fail(1, "baud", QT_TRANSLATE_NOOP("Refusal", "not a supported speed"));
    if (m.parity && (*m.parity < 0 || *m.parity > 2))
        r.fail(2, "parity", QT_TRANSLATE_NOOP("Refusal", "not 0, 1 or 2"));
}
} // namespace

bool decodeSerialPort(const Sentence &s, DecodeContext &ctx) {
    return decodeWith<SerialPort>(s, ctx, 0, [](FieldReader &r, SerialPort &m) {
        readFields(r, m, kFields);
        checkSerialPort(r, m);
    });
}

void SerialPort::writeJson(JsonWriter &w) const {
    const char *parities[] = {"none", "odd", "even"};
    w.beginObject().field("protocol", protocol);
    w.key("protocol_name");
    if (protocol)
        w.value(*protocol == 0 ? "NMEA" : "Nemerix binary");
    else
        w.null();
    w.field("baud", baud).field("parity", parity).key("parity_name");
    if (parity && *parity >= 0 && *parity <= 2)
        w.value(parities[*parity]);
    else
        w.null();
    w.endObject();
}

EncodeResult encodeSerialPort(int protocol, int baud, int parity, std::string_view prefix) {
    EncodeResult r;
    if (protocol < 0 || protocol > 1)
        r.error = "protocol: " + std::to_string(protocol) +
                  " is out of range; accepted: 0 (NMEA) or 1 (Nemerix binary)";
    else if (!knownBaud(baud))
        r.error = "baud: " + std::to_string(baud) +
                  " is not supported; accepted: " + baudList(kSupportedBauds);
    else if (parity < 0 || parity > 2)
        r.error = "parity: " + std::to_string(parity) +
                  " is out of range; accepted: 0 (none), 1 (odd), 2 (even)";
    if (!r.ok()) return r;
    return buildCommand("100",
                        "," + std::to_string(protocol) + "," + std::to_string(baud) + "," +
                                std::to_string(parity),
                        prefix);
}

} // namespace gnss::nemerix
