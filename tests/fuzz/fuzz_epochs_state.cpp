// Fuzz harness: bytes → StreamDecoder → EpochAssembler (what `gnss-cli epochs` prints) and
// StateTracker (the ReceiverState the views show), as the application wires them.
//
// Input: byte 0 picks the decoder options (fuzz_nmea.h), byte 1 a chunking, the rest is the
// stream. Checks that every epoch's JSON is valid, that the assembler's epoch count matches
// the epochs it emitted, that the time-mark list stays bounded, and that the chunked run gives
// exactly the epochs and snapshots of a one-shot run.
#include "fuzz_nmea.h"
#include "state/epoch_assembler.h"
#include "state/state_tracker.h"

using namespace gnss;
using namespace gnss::fuzz;

namespace {

// Every field of a snapshot a view reads, as text (the epoch in its own JSON).
GNSS_FUZZ_NO_COVERAGE std::string snapshot(const ReceiverState &s, bool validate) {
    std::string out;
    JsonWriter w(out);
    w.beginObject().key("epoch");
    s.epoch.writeJson(w);
    const RtkState &r = s.rtk;
    w.field("rtk_seen", r.seen).field("mode", r.mode).field("rtcm_total", r.rtcmTotal);
    w.field("rtcm_errors", r.rtcmErrors).field("rtcm_ok", r.rtcmOk);
    w.field("base_distance", r.baseDistance).field("age", r.correctionAge);
    w.field("base_id", r.baseStationId).field("heading", r.heading);
    for (const BaselineState *b : {&r.baseToRover, &r.antennas})
        w.field("n", b->north)
                .field("e", b->east)
                .field("v", b->vertical)
                .field("len", b->length)
                .field("course", b->course)
                .field("pitch", b->pitch)
                .field("bmode", b->mode);
    w.field("sd", r.sdLat).field("sd", r.sdLon).field("sd", r.sdHeight);
    w.field("sdv", r.sdVelNorth).field("sdv", r.sdVelEast).field("sdv", r.sdVelUp);
    w.field("sdh", r.sdHeading);
    for (const auto &d : {r.gdop, r.pdop, r.hdop, r.vdop, r.tdop, r.ndop, r.edop})
        w.field("dop", d);
    w.field("vel", r.velNorth).field("vel", r.velEast).field("vel", r.velUp);
    const AttitudeState &a = s.attitude;
    w.field("att_seen", a.seen).field("att_time", a.time).field("roll", a.roll);
    w.field("pitch", a.pitch).field("yaw", a.yaw).field("acc", a.accNorth);
    w.field("acc", a.accEast).field("acc", a.accDown);
    w.field("time_marks", static_cast<std::uint64_t>(s.timeMarks.size()));
    if (!s.timeMarks.empty()) {
        const TimeMarkEvent &t = s.timeMarks.back();
        w.field("counter", t.counter).field("tow", t.towSeconds).field("utc", t.utc);
        w.field("lat", t.lat).field("lon", t.lon).field("alt", t.altMsl);
    }
    const ReceiverIdentity &id = s.identity;
    w.field("vendor", id.vendor).field("model", id.model).field("firmware", id.firmware);
    w.field("hardware", id.hardware).key("reports").beginObject();
    for (const auto &[title, json] : s.reports) {
        if (validate) checkJson(json, "a status report's JSON is not valid JSON");
        w.key(title).raw(json);
    }
    w.endObject().field("jamming", s.jamming).endObject();
    return out;
}

struct Run {
    std::vector<std::string> epochs;    // EpochAssembler, as `gnss-cli epochs` prints them
    std::vector<std::string> snapshots; // StateTracker
};

// `validate`: check the JSON too (one of two runs over the same bytes is enough).
Run run(std::string_view bytes, const DecoderOptions &options,
        const std::vector<std::size_t> &sizes, bool validate) {
    StreamDecoder dec(registry(), options);
    EpochAssembler assembler(dec.dialect());
    StateTracker tracker(dec.dialect());
    Run r;
    auto onEpoch = [&](const Epoch &e) {
        std::string json;
        JsonWriter w(json);
        e.writeJson(w);
        if (validate) checkJson(json, "an epoch's JSON is not valid JSON");
        r.epochs.push_back(std::move(json));
    };
    auto onState = [&](const ReceiverState &s) {
        check(s.timeMarks.size() <= ReceiverState::kMaxTimeMarks, "time marks unbounded");
        r.snapshots.push_back(snapshot(s, validate));
    };
    std::size_t pos = 0;
    for (std::size_t n : sizes) {
        dec.feed(bytes.substr(pos, n), [&](const SentenceEvent &ev) {
            if (!ev.message) return;
            assembler.setDialect(dec.dialect());
            assembler.add(ev.sentence, *ev.message, onEpoch);
            tracker.setDialect(dec.dialect());
            tracker.add(ev.sentence, *ev.message, ev.dialect, onState);
        });
        pos += n;
    }
    dec.finish();
    assembler.flush(onEpoch);
    tracker.flush(onState);
    checkEqual<std::uint64_t>(assembler.epochs(), r.epochs.size(),
                              "EpochAssembler::epochs() != epochs emitted");
    r.snapshots.push_back(snapshot(tracker.state(), validate));
    return r;
}

GNSS_FUZZ_NO_COVERAGE void checkSame(const std::vector<std::string> &a,
                                     const std::vector<std::string> &b, const char *what) {
    if (a.size() != b.size())
        fail(what, std::to_string(a.size()) + " and " + std::to_string(b.size()) + " items");
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) fail(what, a[i] + "\n  vs\n  " + b[i]);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const StreamInput in(data, size);
    const Run whole = run(in.bytes, in.options, {in.bytes.size()}, true);
    const Run chunked = run(in.bytes, in.options, chunking(in.chunkSeed, in.bytes.size()), false);
    checkSame(whole.epochs, chunked.epochs, "chunking changed the epochs");
    checkSame(whole.snapshots, chunked.snapshots, "chunking changed the receiver state");
    return 0;
}
