// NVS messages → the vendor-neutral receiver state (RTK status, RTA heading, IMU attitude, time
// marks, identity, self-test), so the views never see a PNVG sentence.
#include "nvs/nvs_state.h"
#include "nvs/nvs_messages.h"
#include "state/receiver_state.h"
#include "state/report_json.h"

namespace gnss::nvs {
namespace {

void copyBaseline(const Baseline &b, BaselineState &out) {
    out.north = b.north;
    out.east = b.east;
    out.vertical = b.vertical;
    out.length = b.length;
    out.course = b.course;
    out.pitch = b.pitch;
    out.mode = b.mode;
}

// PNVGTME, PNVGTMU and PNVGTMC describe one event: merge them by counter (TMC has none and
// joins the latest event).
TimeMarkEvent &timeMark(ReceiverState &st, std::optional<std::int64_t> counter) {
    if (!st.timeMarks.empty() &&
        (!counter || !st.timeMarks.back().counter || *st.timeMarks.back().counter == *counter)) {
        TimeMarkEvent &last = st.timeMarks.back();
        if (!last.counter) last.counter = counter;
        return last;
    }
    TimeMarkEvent e;
    e.counter = counter;
    st.addTimeMark(e);
    return st.timeMarks.back();
}

} // namespace

bool updateState(const Message &m, ReceiverState &st) {
    RtkState &rtk = st.rtk;
    if (const auto *v = message_cast<Ver>(m)) {
        st.identity.vendor = "NVS";
        // The device id is "RTK" or "RTA"; the product of the latter is the NV08C-RTK-A.
        const std::string device(v->device.value_or("RTK"));
        st.identity.model = device == "RTA" ? std::string("NV08C-RTK-A") : "NV08C-" + device;
        st.identity.firmware = std::string(v->rtkFw.value_or(""));
        // Appended, not `" " + std::string(…)`: GCC 12's Release build warned of an overlapping
        // memcpy (-Wrestrict) in that concatenation.
        std::string hardware(v->csmHw.value_or(""));
        if (v->csmFw) hardware.append(" ").append(*v->csmFw);
        st.identity.hardware = std::move(hardware);
        st.reports["Version"] = messageJson(m);
        return true;
    }
    if (const auto *b = message_cast<Bss>(m)) {
        rtk.seen = true;
        rtk.rtcmTotal = b->rtcmTotal;
        rtk.rtcmErrors = b->rtcmErrors;
        rtk.rtcmOk = b->rtcmOk;
        rtk.baseDistance = b->baseDistance;
        rtk.correctionAge = b->rtcmAge;
        return true;
    }
    if (const auto *b = message_cast<Brs>(m)) {
        rtk.seen = true;
        copyBaseline(*b, rtk.baseToRover);
        if (b->mode) rtk.mode = b->mode;
        return true;
    }
    if (const auto *b = message_cast<Bls>(m)) {
        rtk.seen = true;
        copyBaseline(*b, rtk.antennas);
        if (b->course) rtk.heading = b->course;
        return true;
    }
    if (const auto *v = message_cast<Vog>(m)) {
        rtk.velNorth = v->velNorth;
        rtk.velEast = v->velEast;
        rtk.velUp = v->velUp;
        return true;
    }
    if (const auto *s = message_cast<Sdp>(m)) {
        rtk.seen = true;
        rtk.sdLat = s->sdLat;
        rtk.sdLon = s->sdLon;
        rtk.sdHeight = s->sdHeight;
        if (s->mode) rtk.mode = s->mode;
        return true;
    }
    if (const auto *s = message_cast<Sdv>(m)) {
        rtk.sdVelNorth = s->sdVelNorth;
        rtk.sdVelEast = s->sdVelEast;
        rtk.sdVelUp = s->sdVelUp;
        return true;
    }
    if (const auto *s = message_cast<Sdh>(m)) {
        rtk.sdHeading = s->sdHeading;
        return true;
    }
    if (const auto *d = message_cast<Dop>(m)) {
        rtk.gdop = d->gdop;
        rtk.pdop = d->pdop;
        rtk.hdop = d->hdop;
        rtk.vdop = d->vdop;
        rtk.tdop = d->tdop;
        rtk.ndop = d->ndop;
        rtk.edop = d->edop;
        return true;
    }
    if (const auto *i = message_cast<Imu>(m)) {
        AttitudeState &a = st.attitude;
        a.seen = true;
        a.time = i->time;
        a.roll = i->roll;
        a.pitch = i->pitch;
        a.yaw = i->yaw;
        a.accNorth = i->accNorth;
        a.accEast = i->accEast;
        a.accDown = i->accDown;
        return true;
    }
    if (const auto *t = message_cast<Tme>(m)) {
        timeMark(st, t->counter).towSeconds = t->tow;
        return true;
    }
    if (const auto *t = message_cast<Tmu>(m)) {
        timeMark(st, t->counter).utc = t->time;
        return true;
    }
    if (const auto *t = message_cast<Tmc>(m)) {
        TimeMarkEvent &e = timeMark(st, std::nullopt);
        e.lat = t->lat;
        e.lon = t->lon;
        e.altMsl = t->altMsl;
        if (!e.utc) e.utc = t->time;
        return true;
    }
    return keepReport<Tst>(m, st, "Self-test") || keepReport<Pps>(m, st, "Time pulse");
}

} // namespace gnss::nvs
