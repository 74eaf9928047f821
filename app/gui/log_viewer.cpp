#include "gui/log_viewer.h"

#include "core/dialect_registry.h"
#include "core/json_writer.h"
#include "logview/log_time.h"
#include "logview/timeline_panel.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QTimeZone>
#include <cmath>

namespace gnss::app {

namespace {
constexpr int kPollMs = 100;            // indexing progress
constexpr int kPlayTickMs = 40;         // 25 updates a second while playing
constexpr int kFollowMs = 1000;         // a growing file is looked at once a second
constexpr int kMessagesDelayMs = 200;   // a range being dragged is counted when it rests
constexpr std::size_t kJumpEpochs = 50; // a move further than this starts the charts afresh
constexpr qint64 kUntimedEpochMs = 100; // pace of epochs without a time (10 Hz)

// The engine's format of an export of the track (GPX, KML, CSV, NMEA).
logview::ExportFormat trackFormat(LogViewer::Export f) {
    switch (f) {
    case LogViewer::Export::Gpx: return logview::ExportFormat::Gpx;
    case LogViewer::Export::Kml: return logview::ExportFormat::Kml;
    case LogViewer::Export::Csv: return logview::ExportFormat::Csv;
    default: return logview::ExportFormat::Nmea;
    }
}
} // namespace

LogViewer::LogViewer(const DialectRegistry &registry, ui::SessionModels models, QObject *parent)
    : QObject(parent), registry_(registry), models_(models) {
    pollTimer_.setInterval(kPollMs);
    connect(&pollTimer_, &QTimer::timeout, this, &LogViewer::poll);
    playTimer_.setInterval(kPlayTickMs);
    connect(&playTimer_, &QTimer::timeout, this, &LogViewer::tick);
    followTimer_.setInterval(kFollowMs);
    connect(&followTimer_, &QTimer::timeout, this, &LogViewer::follow);
    messagesDelay_.setSingleShot(true);
    messagesDelay_.setInterval(kMessagesDelayMs);
    connect(&messagesDelay_, &QTimer::timeout, this, &LogViewer::publishMessages);
    connect(&cursor_, &ui::LogCursor::moved, this, [this](std::size_t k) {
        if (!advancing_ && playing()) anchorPlay();
        if (view_ && !cursor_.empty()) publish(k);
    });
    connect(&cursor_, &ui::LogCursor::rangeChanged, this, [this] {
        if (view_ && !cursor_.empty()) messagesDelay_.start();
    });
}

LogViewer::~LogViewer() {
    stop_->store(true);
    for (const QPointer<QThread> &t : workers_)
        if (t) t->wait();
}

template <class Work, class Done> void LogViewer::runAsync(Work work, Done done) {
    const quint64 generation = generation_;
    auto *thread = QThread::create([this, work = std::move(work), done = std::move(done),
                                    generation, stop = stop_]() mutable {
        auto result = work();
        if (stop->load()) return;
        QMetaObject::invokeMethod(
                this,
                [this, done = std::move(done), result = std::move(result), generation]() mutable {
                    if (generation == generation_) done(std::move(result));
                },
                Qt::QueuedConnection);
    });
    connect(thread, &QThread::finished, thread, &QObject::deleteLater);
    std::erase_if(workers_, [](const QPointer<QThread> &t) { return t.isNull(); });
    workers_.emplace_back(thread);
    thread->start();
}

void LogViewer::open(const QString &path, const QString &at) {
    close();
    ++generation_;
    path_ = path;
    startAt_ = at;
    view_ = std::make_shared<logview::LogView>(registry_, viewOptions_);
    firstShown_ = readyNoted_ = havePublished_ = cancelling_ = followBusy_ = false;
    if (models_.state) models_.state->clear();
    if (models_.satellites) models_.satellites->clear();
    if (models_.messages) models_.messages->clear();
    if (models_.console) models_.console->clear();
    view_->open(QFile::encodeName(path).toStdString());
    cursor_.setLog(view_.get());
    lines_.setLog(view_, [this](std::uint64_t offset) {
        const auto e = view_ ? view_->epochAtOffset(offset) : std::nullopt;
        return e ? epochMs(*e) : qint64(0);
    });
    pollTimer_.start();
    poll();
}

void LogViewer::close() {
    if (!view_) return;
    setPlaying(false);
    setFollowing(false);
    pollTimer_.stop();
    messagesDelay_.stop();
    ++generation_;
    exporting_ = false;
    followBusy_ = false; // a follow still running finishes on the old log; its report is dropped //
                         // an export still running finishes its file; its report is dropped
    cursor_.setLog(nullptr);
    lines_.setLog(nullptr, {});
    view_->cancel();
    view_.reset(); // a worker still reading keeps its own reference
    path_.clear();
    emit progress(-1, {});
    emit statusChanged();
}

bool LogViewer::indexing() const {
    if (!view_) return false;
    using Phase = logview::LogView::Phase;
    const auto phase = view_->progress().phase;
    return phase == Phase::Idle || phase == Phase::Inflating || phase == Phase::Indexing;
}

void LogViewer::cancelIndexing() {
    if (!indexing()) return;
    view_->cancel(); // the worker stops within a megabyte; poll() sees it and says so
    cancelling_ = true;
    emit statusChanged();
}

const Dialect *LogViewer::dialectAtCursor() const {
    const auto r = view_ && !cursor_.empty() ? view_->epoch(cursor_.current()) : std::nullopt;
    const auto all = registry_.dialects();
    return r && r->dialect > 0 && r->dialect <= all.size() ? all[r->dialect - 1] : nullptr;
}

bool LogViewer::failed() const {
    if (!view_) return false;
    const auto phase = view_->progress().phase;
    return phase == logview::LogView::Phase::Failed ||
           (phase == logview::LogView::Phase::Ready && view_->epochCount() == 0);
}

QString LogViewer::statusText() const {
    if (!view_) return {};
    const QString name = QFileInfo(path_).fileName();
    const auto p = view_->progress();
    using Phase = logview::LogView::Phase;
    switch (p.phase) {
    case Phase::Idle:
    case Phase::Inflating:
        if (cancelling_) return tr("Log %1: cancelling…").arg(name);
        return tr("Log %1: unpacking, %2 %").arg(name).arg(qRound(p.fraction * 100));
    case Phase::Indexing:
        if (cancelling_) return tr("Log %1: cancelling…").arg(name);
        return tr("Log %1: indexing, %2 % of %3 MB")
                .arg(name)
                .arg(qRound(p.fraction * 100))
                .arg(double(p.bytesTotal) / 1e6, 0, 'f', 1);
    case Phase::Cancelled:
        if (view_->epochCount() > 0)
            return tr("Log %1: indexing cancelled at %2 %: the first %3 epochs are shown (open "
                      "it again to index it all)")
                    .arg(name)
                    .arg(view_->fileSize() ? qRound(100.0 * double(view_->indexedEnd()) /
                                                    double(view_->fileSize()))
                                           : 0)
                    .arg(view_->epochCount());
        return tr("Log %1: indexing cancelled (open it again to index it)").arg(name);
    case Phase::Failed: return tr("Log %1: %2").arg(name, QString::fromStdString(view_->error()));
    case Phase::Ready: break;
    }
    const auto warnings = view_->warnings();
    if (view_->epochCount() == 0)
        return warnings.empty() ? tr("Log %1: no epochs found").arg(name)
                                : tr("Log %1: %2").arg(name, QString::fromStdString(warnings[0]));
    QString text = tr("Log %1: %2 epochs").arg(name).arg(view_->epochCount());
    if (!warnings.empty()) text += tr(" · %1").arg(QString::fromStdString(warnings.back()));
    if (following()) text += tr(" · following");
    return text;
}

void LogViewer::poll() {
    if (!view_) return;
    const auto p = view_->progress();
    using Phase = logview::LogView::Phase;
    if (p.phase == Phase::Inflating || p.phase == Phase::Indexing || p.phase == Phase::Idle) {
        emit progress(p.fraction, statusText());
        if (!firstShown_) showFirstEpoch();
    } else {
        pollTimer_.stop();
        emit progress(-1, statusText());
        // Cancelled, the epochs indexed before are shown as a log of their own.
        const bool usable =
                p.phase == Phase::Ready || (p.phase == Phase::Cancelled && view_->epochCount() > 0);
        if (usable && !readyNoted_) {
            readyNoted_ = true;
            countLines();
            cursor_.notifyIndexChanged();
            std::optional<std::size_t> start;
            QString refused;
            if (const auto spec = logview::parseTimeSpec(startAt_.toStdString())) {
                const logview::TimeLookup at = logview::lookUpTime(*view_, *spec);
                if (at.place == logview::TimePlace::Inside)
                    start = at.epoch;
                else
                    refused = ui::TimelinePanel::refusalText(*view_, at.place, startAt_);
            }
            if (!cursor_.empty()) cursor_.seek(start.value_or(0), true);
            if (!refused.isEmpty()) emit startRefused(refused);
            publishMessages();
            emit indexed();
        }
    }
    emit statusChanged();
}

void LogViewer::showFirstEpoch() {
    const auto r = view_->firstEpoch();
    if (!r || !models_.state) return;
    // Before the index is done there is no state to rebuild: what the first epoch's record has.
    ReceiverState s;
    s.epoch.fix = r->fixType();
    if (r->hasPosition()) {
        s.epoch.lat = r->lat;
        s.epoch.lon = r->lon;
        if (!std::isnan(r->altMsl)) s.epoch.altMsl = r->altMsl;
    }
    if (!std::isnan(r->hdop)) s.epoch.hdop = r->hdop;
    if (r->sats != 255) s.epoch.satsUsed = r->sats;
    const qint64 ms = r->hostMs != logview::kNoTime ? r->hostMs : r->hasTime() ? r->utcMs : 0;
    models_.state->publish(s, QDateTime::fromMSecsSinceEpoch(ms, QTimeZone::utc()));
    firstShown_ = true;
}

qint64 LogViewer::epochMs(std::size_t k) const {
    const auto r = view_ ? view_->epoch(k) : std::nullopt;
    if (!r) return qint64(k) * kUntimedEpochMs;
    if (r->hostMs != logview::kNoTime) return r->hostMs;
    if (r->hasTime()) return r->utcMs;
    return qint64(k) * kUntimedEpochMs;
}

void LogViewer::publish(std::size_t k) {
    if (!view_) return;
    QElapsedTimer t;
    t.start();
    ReceiverState s;
    if (!view_->stateAt(k, s)) return;
    const bool jump = !havePublished_ || k < lastPublished_ || k > lastPublished_ + kJumpEpochs;
    if (jump) {
        if (models_.state) models_.state->clear();
        if (models_.satellites) models_.satellites->clear();
    }
    const qint64 ms = epochMs(k);
    if (models_.state)
        models_.state->publish(s, QDateTime::fromMSecsSinceEpoch(ms, QTimeZone::utc()));
    if (models_.satellites) models_.satellites->update(s.epoch, ms);
    showCursorLines(k);
    lastPublished_ = k;
    havePublished_ = true;
    lastPublishMs_ = double(t.nsecsElapsed()) / 1e6;
}

void LogViewer::showCursorLines(std::size_t k) {
    // The console is the file itself (a virtual list over the mapping): the cursor's epoch is
    // marked there and its last line brought into view.
    const std::uint64_t begin = k > 0 ? view_->epochEnd(k - 1) : 0;
    lines_.setCursor(begin, view_->epochEnd(k));
}

void LogViewer::countLines() {
    // About 0.3 s a gigabyte: on a worker, like the index; the console's rows appear after it.
    runAsync([view = view_, stop = stop_] { return view->indexLines(stop.get()); },
             [this](std::uint64_t lines) { lines_.setLineCount(lines); });
}

void LogViewer::publishMessages() {
    if (!view_ || cursor_.empty() || !models_.messages) return;
    const auto [first, last] = cursor_.selection();
    const quint64 asked = ++messagesAsked_;
    const qint64 endMs = epochMs(last);
    // Counting a range decodes its bytes: off the GUI thread (a whole 1 GB log takes a second).
    runAsync([view = view_, first = first, last = last] { return view->messageStats(first, last); },
             [this, asked, endMs](std::vector<AddressStats> stats) {
                 if (asked != messagesAsked_) return;
                 models_.messages->clear();
                 models_.messages->refresh(stats, endMs);
             });
}

void LogViewer::setPlaying(bool on) {
    if (on == playing()) return;
    if (on && (cursor_.empty() || !view_)) return;
    if (on) {
        if (cursor_.current() + 1 >= cursor_.epochCount()) cursor_.seek(0);
        anchorPlay();
        playTimer_.setInterval(speed_ > 0 ? kPlayTickMs : 0);
        playTimer_.start();
    } else {
        playTimer_.stop();
    }
    emit playingChanged(on);
}

void LogViewer::setSpeed(double factor) {
    speed_ = factor;
    if (playing()) {
        playTimer_.setInterval(speed_ > 0 ? kPlayTickMs : 0);
        anchorPlay();
    }
}

void LogViewer::anchorPlay() {
    playClock_.start();
    playEpoch_ = cursor_.current();
    playLogMs_ = epochMs(playEpoch_);
}

void LogViewer::tick() {
    const std::size_t n = cursor_.epochCount();
    std::size_t k = cursor_.current();
    if (n == 0 || k + 1 >= n) {
        if (!following()) setPlaying(false);
        return;
    }
    if (speed_ <= 0) {
        ++k; // as fast as possible: every epoch, as fast as the views draw
    } else {
        // Paced by the log's own clock: the last epoch whose time has come.
        const double target = double(playLogMs_) + double(playClock_.elapsed()) * speed_;
        bool reanchor = false;
        while (k + 1 < n) {
            const qint64 next = epochMs(k + 1), cur = epochMs(k);
            if (next < cur) { // the time went back (a reset): go on from there
                ++k;
                reanchor = true;
                break;
            }
            if (double(next) > target) break;
            ++k;
        }
        if (k == cursor_.current()) return;
        advancing_ = true;
        cursor_.seek(k);
        advancing_ = false;
        if (reanchor) anchorPlay();
        return;
    }
    advancing_ = true;
    cursor_.seek(k);
    advancing_ = false;
}

void LogViewer::setFollowing(bool on) {
    if (on == following()) return;
    if (on && view_)
        followTimer_.start();
    else
        followTimer_.stop();
    emit statusChanged();
}

void LogViewer::follow() {
    if (!view_ || !ready() || followBusy_) return;
    followBusy_ = true;
    // What the file gained (megabytes, maybe) is indexed on a worker; the engine swaps the new
    // records in under a short lock, so the views go on drawing meanwhile.
    runAsync([view = view_] { return view->follow(); },
             [this](logview::LogView::FollowResult r) {
                 followBusy_ = false;
                 if (!r.grew && !r.truncated) return;
                 countLines();
                 // The cursor's count is still the one before the growth.
                 const bool atEnd =
                         cursor_.empty() || cursor_.current() + 1 >= cursor_.epochCount();
                 cursor_.notifyIndexChanged();
                 if (atEnd && !cursor_.empty()) cursor_.seek(cursor_.epochCount() - 1, true);
                 messagesDelay_.start();
                 emit indexed();
                 emit statusChanged();
             });
}

std::optional<LogViewer::Export> LogViewer::formatOfSuffix(const QString &suffix) {
    const QString s = suffix.toLower();
    if (s == QLatin1String("gpx")) return Export::Gpx;
    if (s == QLatin1String("kml")) return Export::Kml;
    if (s == QLatin1String("csv")) return Export::Csv;
    if (s == QLatin1String("nmea") || s == QLatin1String("log") || s == QLatin1String("txt"))
        return Export::Nmea;
    if (s == QLatin1String("json")) return Export::StatsJson;
    return std::nullopt;
}

bool LogViewer::exportTo(Export format, const QString &path, QString *why) {
    if (!view_ || cursor_.empty()) {
        if (why) *why = tr("no log is open, or it is still being indexed");
        return false;
    }
    if (exporting_) {
        if (why) *why = tr("an export is already running");
        return false;
    }
    const auto [first, last] = cursor_.selection();
    exporting_ = true;
    const std::string file = QFile::encodeName(path).toStdString();
    const std::string name = QFileInfo(path_).completeBaseName().toStdString();
    const bool stationary = false;
    runAsync(
            [view = view_, format, file, name, first = first, last = last, stop = stop_,
             stationary]() -> QString {
                std::FILE *f = std::fopen(file.c_str(), "wb");
                if (!f) return QStringLiteral("cannot write");
                const logview::ExportSink sink = [f, stop](std::string_view b) {
                    return !stop->load() && std::fwrite(b.data(), 1, b.size(), f) == b.size();
                };
                bool ok = true;
                switch (format) {
                case Export::Gpx:
                case Export::Kml:
                case Export::Csv:
                case Export::Nmea:
                    ok = view->exportRange(trackFormat(format), first, last, sink, name);
                    break;
                case Export::StatsJson: {
                    std::string out;
                    JsonWriter w(out);
                    view->stats(first, last, stationary).writeJson(w);
                    out += '\n';
                    ok = sink(out);
                    break;
                }
                case Export::EventsCsv: {
                    std::vector<logview::LogEvent> in;
                    for (auto &e : view->events())
                        if (e.epoch >= first && e.epoch <= last) in.push_back(std::move(e));
                    ok = sink(logview::eventsCsv(in));
                    break;
                }
                }
                ok = std::fclose(f) == 0 && ok;
                return ok ? QString() : QStringLiteral("write failed");
            },
            [this, path, first = first, last = last](QString error) {
                exporting_ = false;
                emit exportFinished(error.isEmpty(),
                                    error.isEmpty()
                                            ? tr("Exported epochs %1 to %2 to %3")
                                                      .arg(first)
                                                      .arg(last)
                                                      .arg(path)
                                            : tr("Could not write %1 (the disk is full, or the "
                                                 "folder is not writable)")
                                                      .arg(path));
            });
    return true;
}

} // namespace gnss::app
