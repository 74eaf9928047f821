// Reference station messages: 1005/1006 (antenna reference point) and 1007/1008/1033 (antenna
// and receiver descriptors).
#include "rtcm/message_decoders.h"

namespace gnss::rtcm {

// 1005 / 1006: stationary RTK reference station ARP (152 / 168 bits).
//
//   field                                   DF     bits
//   message number                          002    12   (read by decodeMessage)
//   reference station id                    003    12
//   ITRF realisation year                   021     6
//   GPS indicator                           022     1
//   GLONASS indicator                       023     1
//   Galileo indicator (reserved in 3.0)     024     1
//   reference-station indicator             141     1
//   ARP ECEF-X, 0.0001 m                    025    38 int
//   single receiver oscillator indicator    142     1
//   reserved                                001     1
//   ARP ECEF-Y, 0.0001 m                    026    38 int
//   quarter cycle indicator                 364     2
//   ARP ECEF-Z, 0.0001 m                    027    38 int
//   antenna height, 0.0001 m (1006 only)    028    16 uint
void decodeStationArp(BitReader &r, RtcmMessage &m) {
    StationArp a;
    if (r.has(12)) m.station = a.station = static_cast<unsigned>(r.u(12));
    a.itrfYear = static_cast<unsigned>(r.u(6));
    a.gps = r.flag();
    a.glonass = r.flag();
    a.galileo = r.flag();
    a.nonPhysical = r.flag();
    // Divided rather than multiplied by 0.0001 so 1114104.5999 stays 1114104.5999 when printed.
    a.x = static_cast<double>(r.s(38)) / 1e4;
    a.singleReceiverOscillator = r.flag();
    r.skip(1);
    a.y = static_cast<double>(r.s(38)) / 1e4;
    a.quarterCycle = static_cast<unsigned>(r.u(2));
    a.z = static_cast<double>(r.s(38)) / 1e4;
    if (m.number == 1006) a.antennaHeight = static_cast<double>(r.u(16)) / 1e4;
    if (!r.ok()) {
        m.error = "truncated";
        return;
    }
    a.position = wgs84::toGeodetic({a.x, a.y, a.z});
    m.body = std::move(a);
}

// 1007 / 1008 / 1033: antenna descriptor, serial number, receiver. Strings are counted, one
// byte per character (ISO 8859-1); counts are 0..31 by the standard, read as the 8 bits sent.
//
//   field                                   DF     bits
//   message number                          002    12   (read by decodeMessage)
//   reference station id                    003    12
//   antenna descriptor counter N            029     8
//   antenna descriptor                      030     8×N
//   antenna setup id                        031     8
//   -- 1008 and 1033 --
//   antenna serial number counter M         032     8
//   antenna serial number                   033     8×M
//   -- 1033 only --
//   receiver type descriptor counter I      227     8
//   receiver type descriptor                228     8×I
//   receiver firmware version counter J     229     8
//   receiver firmware version               230     8×J
//   receiver serial number counter K        231     8
//   receiver serial number                  232     8×K
void decodeAntennaInfo(BitReader &r, RtcmMessage &m) {
    AntennaInfo a;
    if (r.has(12)) m.station = a.station = static_cast<unsigned>(r.u(12));
    auto counted = [&r] { return r.chars(static_cast<std::size_t>(r.u(8))); };
    a.antennaDescriptor = counted();
    a.setupId = static_cast<unsigned>(r.u(8));
    if (m.number != 1007) a.antennaSerial = counted();
    if (m.number == 1033) {
        a.receiverType = counted();
        a.firmware = counted();
        a.receiverSerial = counted();
    }
    if (!r.ok()) {
        m.error = "truncated";
        return;
    }
    m.body = std::move(a);
}

} // namespace gnss::rtcm
