// Fuzz harness: a recording's index (FILE.nmea.idx, docs/recording.md) as its two readers take
// it: loadRecording (protocol/link: replay, gnss-cli monitor --replay) and HostTimes
// (protocol/logview: the log viewer's host times). Whatever the index holds (torn, cut, another
// program's file, garbage) neither may crash, and:
//   - a refusal names the file and the line;
//   - an accepted recording has the data file's bytes exactly, and chunks that tile them from
//     offset 0 to the end (the bytes past the last indexed chunk at the last known time);
//   - the two readers take the same indexes and refuse the same ones, and where they take one
//     they give the same host time to every byte and the same link gaps;
//   - with bit 2 of byte 0, the log viewer opens the recording: every epoch has the host time of
//     the chunk it arrived in, link gaps mark epochs and become events, a broken index is a
//     warning (the log itself still opens), and the play-out pace is finite and never goes back.
//
// Input: byte 0: bits 0-1 which files exist (0, 3: both; 1: the data only; 2: the index only),
// bit 2 the log viewer; bytes 1-2 the index's length (little endian, cut to what follows); then
// the index, then the data.
#include "fuzz_files.h"
#include "fuzz_nmea.h"
#include "link/recording.h"
#include "logview/host_times.h"
#include "logview/log_view.h"
#include "logview/play_schedule.h"

#include <QString>

#include <cmath>

using namespace gnss;
using namespace gnss::fuzz;
using namespace gnss::logview;

namespace {

GNSS_FUZZ_NO_COVERAGE std::string str(const QString &s) {
    return s.toStdString();
}

// loadRecording: a clear refusal, or the data and chunks that tile it.
void checkLoad(bool ok, const link::Recording &r, const QString &error, bool dataExists,
               bool indexExists, std::string_view dataBytes, const std::string &path) {
    if (!dataExists) {
        check(!ok && error.contains(QString::fromStdString(path)),
              "a missing data file was not refused by name", str(error));
        return;
    }
    if (!ok) {
        check(indexExists, "a recording without an index was refused", str(error));
        check(error.contains(QString::fromStdString(path + ".idx")) &&
                      error.contains(QStringLiteral(", line ")),
              "a refused index does not name its file and line", str(error));
        return;
    }
    check(error.isEmpty(), "an accepted recording came with an error", str(error));
    check(std::string_view(r.bytes.constData(), static_cast<std::size_t>(r.bytes.size())) ==
                  dataBytes,
          "the recording's bytes are not the data file's");
    check(r.hasIndex == indexExists, "hasIndex says otherwise than the file system");
    if (!indexExists) {
        check(r.chunks.empty() && r.events.empty(), "chunks or events without an index");
        return;
    }
    qint64 end = 0;
    for (const link::RecordedChunk &c : r.chunks) {
        check(c.offset == end && c.length >= 0, "the chunks do not tile the data",
              std::to_string(c.offset) + "+" + std::to_string(c.length) + " after " +
                      std::to_string(end));
        end = c.offset + c.length;
    }
    checkEqual<qint64>(end, r.bytes.size(), "the chunks do not cover the data");
    for (const link::RecordedEvent &e : r.events)
        check(e.kind == link::RecordedEvent::Kind::Sent || e.kind == link::RecordedEvent::Kind::Gap,
              "an event of no known kind");
}

// The two readers agree.
void checkAgree(bool linkOk, const link::Recording &r, const QString &linkError,
                const HostTimes &host, bool hostOk) {
    // An index the link refuses, the viewer does not use, and the other way round.
    check(linkOk == host.error().empty(), "the link's and the viewer's readers disagree",
          "link: " + (linkOk ? std::string("accepted") : str(linkError)) +
                  "\n  viewer: " + (host.error().empty() ? "accepted" : host.error()));
    if (!linkOk) return;
    bool anyBytes = false;
    for (const link::RecordedChunk &c : r.chunks) {
        if (c.length == 0) continue;
        anyBytes = true;
        check(host.at(static_cast<std::uint64_t>(c.offset)) == c.hostMs &&
                      host.at(static_cast<std::uint64_t>(c.offset + c.length - 1)) == c.hostMs,
              "the readers give a chunk different host times",
              "offset " + std::to_string(c.offset) + ": " + std::to_string(c.hostMs) + " vs " +
                      std::to_string(host.at(static_cast<std::uint64_t>(c.offset))));
    }
    check(hostOk == anyBytes, "host times without bytes, or bytes without host times");
    if (!hostOk) return;
    std::size_t g = 0;
    for (const link::RecordedEvent &e : r.events) {
        if (e.kind != link::RecordedEvent::Kind::Gap) continue;
        check(g < host.gaps().size(), "the viewer lost a link gap");
        const LinkGap &h = host.gaps()[g++];
        check(h.offset == static_cast<std::uint64_t>(e.offset) && h.hostMs == e.hostMs &&
                      QString::fromUtf8(h.text.data(), static_cast<qsizetype>(h.text.size())) ==
                              e.text,
              "the readers read a link gap differently", h.text + " vs " + str(e.text));
    }
    checkEqual<std::size_t>(g, host.gaps().size(), "the viewer has link gaps the link has not");
}

// The log viewer on the recording.
void checkViewer(const std::string &path, const HostTimes &host, bool hostOk) {
    LogViewOptions o;
    o.index.threads = 1;
    LogView view(registry(), o);
    view.open(path);
    view.waitUntilIndexed();
    check(view.progress().phase == LogView::Phase::Ready, "the viewer did not open the log",
          view.error());
    check(view.hasHostTimes() == hostOk, "the viewer's host times are not HostTimes'");
    if (!host.error().empty()) {
        bool warned = false;
        for (const std::string &w : view.warnings()) warned |= w == host.error();
        check(warned, "a broken index was not a warning", host.error());
    }
    std::vector<EpochRecord> recs;
    view.withRecords(
            [&](std::span<const EpochRecord> all) { recs.assign(all.begin(), all.end()); });
    std::size_t flagged = 0;
    for (const EpochRecord &r : recs) {
        check(r.hostMs == (hostOk ? host.at(r.offset) : kNoTime),
              "an epoch's host time is not its chunk's", std::to_string(r.offset));
        flagged += r.has(kLinkGap);
    }
    std::size_t linkEvents = 0;
    for (const LogEvent &e : view.events()) linkEvents += e.kind == EventKind::LinkGap;
    std::size_t passed = 0;
    if (hostOk && !recs.empty())
        for (const LinkGap &g : host.gaps()) passed += g.offset <= recs.back().offset;
    checkEqual<std::size_t>(linkEvents, passed, "link gaps passed and link events differ");
    check(flagged <= passed && (passed == 0) == (flagged == 0),
          "epochs marked for link gaps do not match the gaps passed");
    for (bool hostTimes : {true, false}) {
        const std::vector<double> due = playSchedule(recs, hostTimes, 3);
        for (std::size_t i = 0; i < due.size(); ++i)
            check(std::isfinite(due[i]) && due[i] >= 0 && (i == 0 || due[i] >= due[i - 1]),
                  "the play-out pace goes back or is not finite");
    }
    std::string csv;
    view.exportRange(ExportFormat::Csv, 0, recs.size(), [&](std::string_view s) {
        csv.append(s);
        return true;
    });
    (void)eventsCsv(view.events());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Input in(data, size);
    const std::uint8_t control = in.byte();
    const bool dataExists = (control & 3) != 2, indexExists = (control & 3) != 1;
    const bool viewer = (control & 4) != 0;
    std::size_t indexLength = in.byte();
    indexLength |= std::size_t{in.byte()} << 8;
    const std::string_view index = in.take(indexLength);
    const std::string_view bytes = in.rest();

    const ScratchDir &dir = ScratchDir::get();
    const std::string path = dir.path("rec.nmea");
    if (dataExists)
        writeFile(path, bytes);
    else
        removeFile(path);
    if (indexExists)
        writeFile(path + ".idx", index);
    else
        removeFile(path + ".idx");

    link::Recording r;
    QString error;
    const bool ok = link::loadRecording(QString::fromStdString(path), r, error);
    checkLoad(ok, r, error, dataExists, indexExists, bytes, path);

    HostTimes host;
    const bool hostOk = host.load(path + ".idx", dataExists ? bytes.size() : 0);
    check(!hostOk || host.error().empty(), "host times taken from an index found broken");
    check(hostOk == !host.empty(), "HostTimes::load's answer is not !empty()");
    if (!indexExists) check(!hostOk && host.error().empty(), "host times without an index");
    if (!host.error().empty())
        check(host.error().find(path + ".idx, line ") == 0,
              "a broken index's warning does not name its file and line", host.error());
    if (dataExists && indexExists) checkAgree(ok, r, error, host, hostOk);
    if (dataExists && viewer) checkViewer(path, host, hostOk);
    return 0;
}
