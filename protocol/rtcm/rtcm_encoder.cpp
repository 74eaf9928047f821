#include "rtcm/rtcm_encoder.h"

#include "rtcm/bit_writer.h"
#include "rtcm/crc24q.h"
#include "rtcm/rtcm_framer.h"

#include <bit>
#include <cmath>

namespace gnss::rtcm {
namespace {

std::int64_t tenthsOfMillimetre(double metres) {
    return std::llround(metres * 1e4);
}

unsigned systemIndex(System s) {
    return static_cast<unsigned>(s);
}

} // namespace

std::string frame(std::span<const std::uint8_t> payload) {
    if (payload.size() > kMaxPayload) return {};
    std::string f;
    f.reserve(payload.size() + kFrameOverhead);
    f.push_back(static_cast<char>(kPreamble));
    f.push_back(static_cast<char>(payload.size() >> 8)); // 6 reserved zero bits + length MSBs
    f.push_back(static_cast<char>(payload.size() & 0xFF));
    f.append(reinterpret_cast<const char *>(payload.data()), payload.size());
    const std::uint32_t crc = crc24q(reinterpret_cast<const std::uint8_t *>(f.data()), f.size());
    f.push_back(static_cast<char>(crc >> 16));
    f.push_back(static_cast<char>(crc >> 8));
    f.push_back(static_cast<char>(crc));
    return f;
}

std::vector<std::uint8_t> stationArpPayload(const StationArp &a) {
    BitWriter w;
    w.u(a.antennaHeight ? 1006 : 1005, 12).u(a.station, 12).u(a.itrfYear, 6);
    w.flag(a.gps).flag(a.glonass).flag(a.galileo).flag(a.nonPhysical);
    w.s(tenthsOfMillimetre(a.x), 38).flag(a.singleReceiverOscillator).zeros(1);
    w.s(tenthsOfMillimetre(a.y), 38).u(a.quarterCycle, 2);
    w.s(tenthsOfMillimetre(a.z), 38);
    if (a.antennaHeight) w.u(static_cast<std::uint64_t>(tenthsOfMillimetre(*a.antennaHeight)), 16);
    return w.bytes();
}

std::vector<std::uint8_t> antennaInfoPayload(unsigned number, const AntennaInfo &a) {
    BitWriter w;
    auto counted = [&w](std::string_view s) {
        s = s.substr(0, 255); // the count is 8 bits
        w.u(s.size(), 8).chars(s);
    };
    w.u(number, 12).u(a.station, 12);
    counted(a.antennaDescriptor);
    w.u(a.setupId, 8);
    if (number != 1007) counted(a.antennaSerial.value_or(""));
    if (number == 1033) {
        counted(a.receiverType.value_or(""));
        counted(a.firmware.value_or(""));
        counted(a.receiverSerial.value_or(""));
    }
    return w.bytes();
}

std::vector<std::uint8_t> msmPayload(const MsmHeader &h) {
    BitWriter w;
    w.u(1070 + 10 * systemIndex(h.system) + h.msmType, 12).u(h.station, 12);
    if (h.system == System::Glonass)
        w.u(h.gloDayOfWeek.value_or(7), 3).u(h.epochMs, 27);
    else
        w.u(h.epochMs, 30);
    w.flag(h.multipleMessage).u(h.iods, 3).zeros(7).u(h.clockSteering, 2).u(h.externalClock, 2);
    w.flag(h.smoothing).u(h.smoothingInterval, 3).u(h.satelliteMask, 64).u(h.signalMask, 32);
    const unsigned nsat = static_cast<unsigned>(std::popcount(h.satelliteMask));
    const unsigned nsig = static_cast<unsigned>(std::popcount(h.signalMask));
    if (nsat * nsig > 64) return w.bytes(); // no valid cell mask exists: header only
    const std::uint64_t cells =
            nsat * nsig == 64 ? h.cellMask : h.cellMask & ((std::uint64_t(1) << (nsat * nsig)) - 1);
    w.u(cells, nsat * nsig);
    w.zeros(msmBodyBits(h.msmType, nsat, static_cast<unsigned>(std::popcount(cells))));
    return w.bytes();
}

// Field by field as in ephemeris_messages.cpp, written out again rather than shared, so a slip in
// one shows up as a round-trip failure or a wrong message length.
std::vector<std::uint8_t> ephemerisPayload(unsigned number, const Ephemeris &e) {
    BitWriter w;
    w.u(number, 12);
    switch (number) {
    case 1019: // GPS, 488 bits
        w.u(e.satellite, 6).u(e.week.value_or(0), 10).zeros(4 + 2 + 14).u(e.iode.value_or(0), 8);
        w.u(e.tocSeconds.value_or(0) / 16, 16).zeros(8 + 16 + 22).u(e.iodc.value_or(0), 10);
        w.zeros(16 + 16 + 32 + 16 + 32 + 16 + 32).u(e.toeSeconds.value_or(0) / 16, 16);
        w.zeros(16 + 32 + 16 + 32 + 16 + 32 + 24 + 8).u(e.health.value_or(0), 6).zeros(2);
        break;
    case 1020: { // GLONASS, 360 bits
        const std::uint32_t tk = e.tkSeconds.value_or(0);
        w.u(e.satellite, 6).u(static_cast<std::uint64_t>(e.frequencyChannel.value_or(0) + 7), 5);
        w.zeros(1 + 1 + 2).u(tk / 3600, 5).u(tk % 3600 / 60, 6).u(tk % 60 >= 30 ? 1 : 0, 1);
        w.u(e.health.value_or(0), 1).zeros(1).u(e.tbMinutes.value_or(0) / 15, 7);
        for (int axis = 0; axis < 3; ++axis) w.sm(0, 24).sm(0, 27).sm(0, 5);
        w.zeros(1).sm(0, 11).zeros(2 + 1).sm(0, 22).sm(0, 5).zeros(5 + 1 + 4 + 11 + 2 + 1 + 11);
        w.sm(0, 32).zeros(5).sm(0, 22).zeros(1 + 7);
        break;
    }
    case 1042: // BeiDou, 511 bits
        w.u(e.satellite, 6).u(e.week.value_or(0), 13).zeros(4 + 14).u(e.iode.value_or(0), 5);
        w.u(e.tocSeconds.value_or(0) / 8, 17).zeros(11 + 22 + 24).u(e.iodc.value_or(0), 5);
        w.zeros(18 + 16 + 32 + 18 + 32 + 18 + 32).u(e.toeSeconds.value_or(0) / 8, 17);
        w.zeros(18 + 32 + 18 + 32 + 18 + 32 + 24 + 10 + 10).u(e.health.value_or(0), 1);
        break;
    case 1044: // QZSS, 485 bits
        w.u(e.satellite, 4).u(e.tocSeconds.value_or(0) / 16, 16).zeros(8 + 16 + 22);
        w.u(e.iode.value_or(0), 8).zeros(16 + 16 + 32 + 16 + 32 + 16 + 32);
        w.u(e.toeSeconds.value_or(0) / 16, 16).zeros(16 + 32 + 16 + 32 + 16 + 32 + 24 + 14 + 2);
        w.u(e.week.value_or(0), 10).zeros(4).u(e.health.value_or(0), 6).zeros(8);
        w.u(e.iodc.value_or(0), 10).zeros(1);
        break;
    case 1045: // Galileo F/NAV, 496 bits
    case 1046: // Galileo I/NAV, 504 bits
        w.u(e.satellite, 6).u(e.week.value_or(0), 12).u(e.iode.value_or(0), 10).zeros(8 + 14);
        w.u(e.tocSeconds.value_or(0) / 60, 14);
        w.zeros(6 + 21 + 31 + 16 + 16 + 32 + 16 + 32 + 16 + 32);
        w.u(e.toeSeconds.value_or(0) / 60, 14).zeros(16 + 32 + 16 + 32 + 16 + 32 + 24 + 10);
        if (number == 1045) {
            w.u(e.e5aHealth.value_or(0), 2).u(e.e5aValidity.value_or(0), 1).zeros(7);
        } else {
            w.zeros(10).u(e.e5bHealth.value_or(0), 2).u(e.e5bValidity.value_or(0), 1);
            w.u(e.e1bHealth.value_or(0), 2).u(e.e1bValidity.value_or(0), 1).zeros(2);
        }
        break;
    default: break; // not an ephemeris: the message number alone
    }
    return w.bytes();
}

std::vector<std::uint8_t> glonassBiasesPayload(const GlonassBiases &b) {
    BitWriter w;
    unsigned mask = 0;
    for (unsigned i = 0; i < 4; ++i)
        if (b.present[i]) mask |= 8u >> i;
    w.u(1230, 12).u(b.station, 12).flag(b.aligned).zeros(3).u(mask, 4);
    for (unsigned i = 0; i < 4; ++i)
        if (b.present[i]) w.s(b.biases[i] ? std::llround(*b.biases[i] * 50.0) : -32768, 16);
    return w.bytes();
}

std::string encodeStationArp(const StationArp &a) {
    return frame(stationArpPayload(a));
}
std::string encodeAntennaInfo(unsigned number, const AntennaInfo &a) {
    return frame(antennaInfoPayload(number, a));
}
std::string encodeMsm(const MsmHeader &h) {
    return frame(msmPayload(h));
}
std::string encodeEphemeris(unsigned number, const Ephemeris &e) {
    return frame(ephemerisPayload(number, e));
}
std::string encodeGlonassBiases(const GlonassBiases &b) {
    return frame(glonassBiasesPayload(b));
}

} // namespace gnss::rtcm
