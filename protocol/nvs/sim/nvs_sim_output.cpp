// What the simulated NV08C-RTK-A sends for each address of its output list (or a query): the
// sky's state as the standard sentences (sim/standard_output.h) and as the NVS messages, built by
// the NVS encoders. The values are the simulator's own (the sky, the base 4.8 km away, the
// heading antennas, time marks); the layouts are the encoders'.
#include "nvs/sim/nvs_sim_receiver.h"

#include "core/wgs84.h"
#include "nvs/nvs_encoders.h"

#include <algorithm>
#include <cmath>

namespace gnss::sim {

namespace {

// What an encoder built; nothing when it refused (the receiver never sends a broken sentence).
std::vector<std::string> sentences(EncodeResult r) {
    return r.ok() ? std::move(r.sentences) : std::vector<std::string>{};
}

} // namespace

StandardStyle NvsReceiver::style() const {
    StandardStyle st;
    st.numbering = Numbering::Nmea40;
    st.format.timeDecimals = static_cast<int>(store_.integer("nmea.time_decimals"));
    st.format.positionDecimals = static_cast<int>(store_.integer("nmea.position_decimals"));
    st.gpTalkerForGgaRmc = store_.integer("nmea.talker_mode") == 0;
    return st;
}

std::optional<TimeOfDay> NvsReceiver::now() const {
    return nmea::timeOfDay(utcSecondOfDay(), style().format.timeDecimals);
}

std::vector<std::string> NvsReceiver::sentencesOf(std::string_view address,
                                                  const SkySnapshot &snap) {
    const std::string a = canonical(address);
    const StandardStyle st = style();
    const EpochTime t{utcSecondOfDay(), utcDate()};
    const char mode = modeIndicator(snap.fix);
    const bool valid = snap.fix != FixKind::None;
    const bool rtk = snap.fix == FixKind::Float || snap.fix == FixKind::Fixed;
    const bool heading = this->mode() == 4 && snap.fix == FixKind::Fixed;
    const double age = lastRtcm_ >= 0 ? time() - lastRtcm_ : -1;
    auto withDifferential = [&](nmea::Gga g) {
        if (rtk && age >= 0) {
            g.dgpsAge = age;
            g.dgpsStation = kBaseStation;
        }
        return g;
    };
    // The epoch's time and mode indicator, as the solution sentences carry them.
    auto stamped = [&](auto m, char modeLetter) {
        m.time = now();
        m.mode = modeLetter;
        return m;
    };
    if (a == "GGA") {
        const auto talker = st.gpTalkerForGgaRmc ? "GP" : solutionTalker(snap, st.numbering);
        return {nmea::encodeGga(talker, withDifferential(ggaOf(snap, t, st.format.timeDecimals)),
                                st.format)};
    }
    if (a == "RMC") return {rmcSentence(snap, t, st)};
    if (a == "VTG") return {vtgSentence(snap, st)};
    if (a == "ZDA") return {zdaSentence(snap, t, st)};
    if (a == "GSA") return gsaSentences(snap, st);
    if (a == "GSV") return gsvSentences(snap, st);
    if (a == "HDT") {
        std::normal_distribution<double> n(0, 0.1);
        return {hdtSentence(heading ? std::optional<double>(heading_ + n(random())) : std::nullopt,
                            st)};
    }
    if (a == nvs::Ver::kType.name) { // an NV08C-RTK-A, RTK firmware 0029
        nvs::Ver v;
        v.manufacturer = "NVS", v.device = "RTA", v.rtkFw = "0029";
        v.csmHw = "CSM24", v.csmFw = "0101";
        return sentences(nvs::encodeVer(v));
    }
    if (a == nvs::Tst::kType.name) { // device 1254367, active antenna connected
        nvs::Tst m;
        m.tests = {{"ID", "1254367"}, {"ANT", "0"}};
        return sentences(nvs::encodeTst(m));
    }
    if (a == nvs::Nme::kType.name || a == nvs::Pps::kType.name) { // as their commands answer
        const std::string r =
                reportOf(a == nvs::Nme::kType.name ? "nmea.time_decimals" : "pps.type");
        return r.empty() ? std::vector<std::string>{} : std::vector<std::string>{r};
    }
    if (a == nvs::Bss::kType.name) {
        nvs::Bss m;
        m.rtcmTotal = rtcmTotal_, m.rtcmErrors = rtcmErrors_, m.rtcmOk = rtcmTotal_ - rtcmErrors_;
        if (rtcmTotal_ > 0) {
            m.baseDistance =
                    std::sqrt(baseNorth_ * baseNorth_ + baseEast_ * baseEast_ + baseUp_ * baseUp_);
            if (age >= 0) m.rtcmAge = std::min(age, nvs::kMaxRtcmAge);
        }
        return sentences(nvs::encodeBss(m));
    }
    if (a == nvs::Brs::kType.name) {
        auto m = stamped(nvs::Brs{}, mode);
        if (valid) {
            const double n = baseNorth_ + snap.errNorth, e = baseEast_ + snap.errEast,
                         u = baseUp_ + snap.errUp;
            const double len = std::sqrt(n * n + e * e + u * u);
            double course = wgs84::degrees(std::atan2(e, n));
            if (course < 0) course += 360;
            m.north = n, m.east = e, m.vertical = u, m.length = len, m.course = course;
            m.pitch = wgs84::degrees(std::asin(u / len));
        }
        return sentences(nvs::encodeBrs(m));
    }
    if (a == nvs::Bls::kType.name || a == nvs::Sdh::kType.name) {
        // ANT1→ANT2: BASELINE metres (0 = unconstrained: the antennas are 1 m apart).
        double len = store_.real("rtk.BASELINE");
        if (len <= 0) len = 1.0;
        const char m = this->mode() == 4 ? mode : 'N';
        const bool ok = this->mode() == 4 && valid;
        std::normal_distribution<double> noise(0, heading ? 0.1 : 2.0);
        const double c = heading_ + noise(random());
        if (a == nvs::Sdh::kType.name) {
            auto sdh = stamped(nvs::Sdh{}, m);
            if (ok) sdh.sdHeading = heading ? 0.2 / len : 3.0;
            return sentences(nvs::encodeSdh(sdh));
        }
        auto bls = stamped(nvs::Bls{}, ok ? m : 'N');
        if (ok) {
            const double pitch = wgs84::radians(-4.0);
            const double h = len * std::cos(pitch);
            bls.north = h * std::cos(wgs84::radians(c)), bls.east = h * std::sin(wgs84::radians(c));
            bls.vertical = len * std::sin(pitch), bls.length = len, bls.course = c;
            bls.pitch = wgs84::degrees(pitch);
        }
        return sentences(nvs::encodeBls(bls));
    }
    if (a == nvs::Imu::kType.name) {
        std::normal_distribution<double> att(0, 0.3), acc(0, 0.05);
        nvs::Imu m;
        m.time = now();
        // Drawn from the last field to the first, as this simulator always has.
        m.accDown = acc(random()) - 0.2, m.accEast = acc(random()), m.accNorth = acc(random());
        m.yaw = heading_ + att(random()), m.pitch = 0.35 + att(random());
        m.roll = 0.4 + att(random());
        return sentences(nvs::encodeImu(m));
    }
    if (a == nvs::Vog::kType.name) {
        auto m = stamped(nvs::Vog{}, mode);
        if (valid) m.velNorth = snap.velNorth, m.velEast = snap.velEast, m.velUp = snap.velUp;
        return sentences(nvs::encodeVog(m));
    }
    if (a == nvs::Sdp::kType.name) {
        auto m = stamped(nvs::Sdp{}, mode);
        if (valid) m.sdLat = snap.sigmaNorth, m.sdLon = snap.sigmaEast, m.sdHeight = snap.sigmaUp;
        return sentences(nvs::encodeSdp(m));
    }
    if (a == nvs::Sdv::kType.name) {
        auto m = stamped(nvs::Sdv{}, mode);
        if (valid) m.sdVelNorth = m.sdVelEast = snap.sigmaVel, m.sdVelUp = snap.sigmaVel * 1.5;
        return sentences(nvs::encodeSdv(m));
    }
    if (a == nvs::Dop::kType.name) {
        auto m = stamped(nvs::Dop{}, mode);
        if (const Dops &d = snap.dops; valid) {
            m.gdop = d.gdop, m.pdop = d.pdop, m.hdop = d.hdop, m.vdop = d.vdop, m.tdop = d.tdop;
            m.ndop = d.ndop, m.edop = d.edop;
        }
        return sentences(nvs::encodeDop(m));
    }
    // The time mark event (one pending since the last epoch): its GPS time, UTC, and the fix
    // at the mark in the GGA layout (4.16-4.18).
    const bool tme = a == nvs::Tme::kType.name, tmu = a == nvs::Tmu::kType.name;
    if (!tme && !tmu && a != nvs::Tmc::kType.name) return {};
    if (!markPending_) return {};
    const double start = kStartSecondOfDay + options().startAfter;
    const double markSod = std::fmod(start + lastMark_, 86400.0);
    if (tme) {
        nvs::Tme m;
        m.counter = markCounter_;
        m.tow = std::fmod(5 * 86400.0 + start + lastMark_ + kLeapSeconds, 604800.0);
        return sentences(nvs::encodeTme(m));
    }
    if (tmu) {
        nvs::Tmu m;
        m.counter = markCounter_;
        m.time = nmea::timeOfDay(markSod, 9);
        return sentences(nvs::encodeTmu(m));
    }
    nvs::Tmc m;
    static_cast<nmea::GgaFields &>(m) =
            withDifferential(ggaOf(markSnap_, EpochTime{markSod, t.date}, st.format.timeDecimals));
    return sentences(nvs::encodeTmc(m, st.format.positionDecimals));
}

} // namespace gnss::sim
