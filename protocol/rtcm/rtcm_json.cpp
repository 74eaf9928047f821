#include "rtcm/rtcm_json.h"

#include "rtcm/observed_signals.h"
#include "rtcm/rtcm_stream_decoder.h"

#include <string>

namespace gnss::rtcm {
namespace {

void writeBody(JsonWriter &w, const StationArp &a) {
    w.field("itrf_year", a.itrfYear);
    w.field("gps", a.gps).field("glonass", a.glonass).field("galileo", a.galileo);
    w.field("non_physical", a.nonPhysical);
    w.field("single_receiver_oscillator", a.singleReceiverOscillator);
    w.field("quarter_cycle", a.quarterCycle);
    w.field("x", a.x).field("y", a.y).field("z", a.z);
    if (a.antennaHeight) w.field("antenna_height", *a.antennaHeight);
    if (a.position) {
        w.field("lat", a.position->latDeg).field("lon", a.position->lonDeg);
        w.field("height", a.position->height);
    }
}

void writeBody(JsonWriter &w, const AntennaInfo &a) {
    w.field("antenna_descriptor", a.antennaDescriptor).field("setup_id", a.setupId);
    if (a.antennaSerial) w.field("antenna_serial", *a.antennaSerial);
    if (a.receiverType) w.field("receiver_type", *a.receiverType);
    if (a.firmware) w.field("firmware", *a.firmware);
    if (a.receiverSerial) w.field("receiver_serial", *a.receiverSerial);
}

void writeBody(JsonWriter &w, const MsmHeader &h) {
    w.field("system", systemName(h.system)).field("msm", h.msmType);
    if (h.gloDayOfWeek)
        w.field("day_of_week", *h.gloDayOfWeek).field("tod_ms", h.epochMs);
    else
        w.field("tow_ms", h.epochMs);
    w.field("multiple_message", h.multipleMessage).field("iods", h.iods);
    w.field("clock_steering", h.clockSteering).field("external_clock", h.externalClock);
    w.field("smoothing", h.smoothing).field("smoothing_interval", h.smoothingInterval);
    w.key("satellites").beginArray();
    for (const auto id : h.satelliteIds()) w.value(unsigned(id));
    w.endArray();
    if (h.system == System::Sbas || h.system == System::Qzss) {
        w.key("prns").beginArray();
        for (const auto id : h.satelliteIds()) w.value(msmPrn(h.system, id));
        w.endArray();
    }
    w.key("signals").beginArray();
    for (const auto id : h.signalIds()) {
        w.beginObject().field("id", unsigned(id));
        if (const auto name = msmSignalName(h.system, id); !name.empty()) w.field("name", name);
        w.endObject();
    }
    w.endArray();
    w.field("cells", unsigned(h.cellCount));
}

void writeBody(JsonWriter &w, const Ephemeris &e) {
    w.field("system", systemName(e.system)).field("satellite", e.satellite);
    if (e.prn != e.satellite) w.field("prn", e.prn);
    auto opt = [&w](std::string_view k, const auto &v) {
        if (v) w.field(k, *v);
    };
    opt("week", e.week);
    opt("iode", e.iode);
    opt("iodc", e.iodc);
    opt("toc", e.tocSeconds);
    opt("toe", e.toeSeconds);
    opt("health", e.health);
    opt("frequency_channel", e.frequencyChannel);
    opt("tk", e.tkSeconds);
    opt("tb_minutes", e.tbMinutes);
    opt("e5a_health", e.e5aHealth);
    opt("e5a_validity", e.e5aValidity);
    opt("e5b_health", e.e5bHealth);
    opt("e5b_validity", e.e5bValidity);
    opt("e1b_health", e.e1bHealth);
    opt("e1b_validity", e.e1bValidity);
}

void writeBody(JsonWriter &w, const GlonassBiases &b) {
    w.field("aligned", b.aligned).field("signals_mask", b.mask);
    w.key("biases").beginObject();
    for (std::size_t i = 0; i < 4; ++i)
        if (b.present[i]) w.field(GlonassBiases::kSignals[i], b.biases[i]);
    w.endObject();
}

void writeSignal(JsonWriter &w, System system, unsigned band, const LegacySignal &s) {
    w.beginObject().field("code", s.code);
    if (const auto name = legacySignalName(system, band, s.code); !name.empty())
        w.field("name", name);
    if (s.pseudorange) w.field("pseudorange", *s.pseudorange);
    if (s.phaseRange) w.field("phase_range", *s.phaseRange);
    w.field("lock_time", s.lockTime);
    if (s.cnr) w.field("cnr", *s.cnr);
    w.endObject();
}

// As an MSM's: system, epoch, "satellites" (ids) and "signals" (RINEX names, observedSignals()),
// then each satellite's values under "observations".
void writeBody(JsonWriter &w, const LegacyObservables &o) {
    w.field("system", systemName(o.system()));
    w.field(o.system() == System::Glonass ? "tod_ms" : "tow_ms", o.epochMs);
    w.field("synchronous", o.synchronous).field("smoothing", o.smoothing);
    w.field("smoothing_interval", o.smoothingInterval);
    const ObservedSignals seen =
            observedSignals(RtcmMessage{.body = o}).value_or(ObservedSignals{});
    w.key("satellites").beginArray();
    for (const unsigned id : seen.satellites) w.value(id);
    w.endArray().key("signals").beginArray();
    for (const auto name : seen.signalNames) w.beginObject().field("name", name).endObject();
    w.endArray().key("observations").beginArray();
    for (const LegacySatellite &s : o.satellites) {
        w.beginObject().field("id", s.id);
        if (s.frequencyChannel) w.field("frequency_channel", *s.frequencyChannel);
        if (s.ambiguity) w.field("ambiguity", *s.ambiguity);
        w.key("l1");
        writeSignal(w, o.system(), 1, s.l1);
        if (s.l2) {
            w.key("l2");
            writeSignal(w, o.system(), 2, *s.l2);
        }
        w.endObject();
    }
    w.endArray();
}

void writeBody(JsonWriter &, const std::monostate &) {}

} // namespace

void writeRtcmJson(JsonWriter &w, const RtcmMessage &m) {
    w.beginObject().field("type", m.number).field("length", std::uint64_t(m.length));
    if (m.station) w.field("station", *m.station);
    std::visit([&w](const auto &body) { writeBody(w, body); }, m.body);
    if (!m.error.empty()) w.field("error", m.error);
    w.endObject();
}

void writeRtcmSummaryJson(JsonWriter &w, const RtcmStreamDecoder &d) {
    const RtcmFramerStats &s = d.framerStats();
    w.beginObject();
    w.field("frames", s.frames).field("bytes", s.bytesIn);
    w.field("bytes_in_frames", s.bytesInFrames).field("bytes_skipped", s.bytesSkipped);
    w.field("crc_failures", s.crcFailures).field("reserved_nonzero", s.reservedNonzero);
    w.field("truncated", s.truncated).field("decode_errors", d.decodeErrors());
    w.key("types").beginObject();
    for (const auto &[type, count] : d.typeCounts()) w.field(std::to_string(type), count);
    w.endObject();
    w.endObject();
}

} // namespace gnss::rtcm
