#include "link/replay_transport.h"

#include "core/sentence.h"

#include <QFileInfo>

#include <algorithm>
#include <utility>

namespace gnss::link {

namespace {

// The pace of a timed replay: slices of 10 ms keep the receiver's own timing within a tick.
constexpr int kReplayTickMs = 10;
// How often an opening replay looks at its worker's progress.
constexpr int kLoadPollMs = 20;

// hhmmss[.sss] → seconds of the day; negative when not a time.
double timeOfDay(std::string_view f) {
    if (f.size() < 6) return -1;
    for (int i = 0; i < 6; ++i)
        if (f[i] < '0' || f[i] > '9') return -1;
    const int h = (f[0] - '0') * 10 + (f[1] - '0');
    const int m = (f[2] - '0') * 10 + (f[3] - '0');
    double s = (f[4] - '0') * 10 + (f[5] - '0');
    if (f.size() > 7 && f[6] == '.') {
        double scale = 0.1;
        for (std::size_t i = 7; i < f.size() && f[i] >= '0' && f[i] <= '9'; ++i, scale /= 10)
            s += (f[i] - '0') * scale;
    }
    if (h > 23 || m > 59 || s >= 61) return -1;
    return h * 3600.0 + m * 60.0 + s;
}

// The UTC time a standard sentence carries, negative when it carries none.
double sentenceTime(std::string_view line) {
    Sentence s;
    if (!s.parse(line) || s.proprietary()) return -1;
    const auto type = s.type();
    if (type == "GGA" || type == "RMC" || type == "ZDA" || type == "GNS" || type == "GST")
        return timeOfDay(s.field(0));
    if (type == "GLL") return timeOfDay(s.field(4));
    return -1;
}

// At most this much is delivered per tick when playing as fast as possible, so a big log
// streams through the event loop instead of arriving as one block.
constexpr qint64 kMaxBytesPerTick = 4 << 20;
// Lines of one time make one slice up to this size (so that an untimed log is not one slice).
constexpr qint64 kMaxSliceBytes = 64 << 10;

} // namespace

struct ReplayTransport::Loaded {
    Recording recording;
    std::vector<Slice> timeline;
    Timing effective = Timing::Auto;
    QString error;
    bool cancelled = false;
};

ReplayTransport::ReplayTransport(QString path, Timing timing, QObject *parent)
    : Transport(parent), path_(std::move(path)), timing_(timing) {
    timer_.setInterval(kReplayTickMs);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &ReplayTransport::tick);
    loadPoll_.setInterval(kLoadPollMs);
    connect(&loadPoll_, &QTimer::timeout, this, &ReplayTransport::pollLoader);
}

ReplayTransport::~ReplayTransport() {
    stopLoader();
}

void ReplayTransport::stopLoader() {
    loadPoll_.stop();
    if (loader_.joinable()) {
        cancelLoad_ = true; // the worker looks at it every few thousand lines
        loader_.join();
        cancelLoad_ = false;
    }
    loaded_.reset(); // a result it left is not applied
    loadDone_ = false;
}

bool ReplayTransport::open() {
    stopLoader();
    timer_.stop();
    const QFileInfo info(path_);
    if (!info.isFile() || !info.isReadable()) {
        fail(tr("Cannot read %1: %2")
                     .arg(path_, info.exists() ? tr("permission denied") : tr("no such file")),
             false);
        return false;
    }
    setState(State::Connecting);
    loadPercent_ = -1;
    percentShown_ = -1;
    loader_ = std::thread([this, path = path_, timing = timing_] {
        auto loaded = std::make_shared<Loaded>();
        auto progress = [this](int percent) {
            loadPercent_.store(percent, std::memory_order_relaxed);
        };
        if (!loadRecording(path, loaded->recording, loaded->error, &cancelLoad_)) {
            loaded->cancelled = loaded->error.isEmpty();
        } else if (timing == Timing::HostTime && !loaded->recording.hasIndex) {
            loaded->error = tr("%1 has no timestamp index (%2): replay it with sentence times "
                               "instead")
                                    .arg(path, indexPathFor(path));
        } else {
            loaded->cancelled = !buildTimeline(loaded->recording, timing, loaded->effective,
                                               loaded->timeline, cancelLoad_, progress);
        }
        loaded_ = std::move(loaded);
        loadDone_.store(true, std::memory_order_release);
    });
    loadPoll_.start();
    return true;
}

void ReplayTransport::pollLoader() {
    const int percent = loadPercent_.load(std::memory_order_relaxed);
    if (percent > percentShown_) {
        percentShown_ = percent;
        emit openingProgress(percent);
    }
    if (!loadDone_.load(std::memory_order_acquire)) return;
    loadPoll_.stop();
    loader_.join(); // it has handed its result over and is ending
    loadDone_ = false;
    finishOpen(std::exchange(loaded_, nullptr));
}

void ReplayTransport::finishOpen(const std::shared_ptr<Loaded> &loaded) {
    if (state() != State::Connecting || loaded->cancelled) return;
    if (!loaded->error.isEmpty()) {
        fail(loaded->error, false);
        return;
    }
    recording_ = std::move(loaded->recording);
    timeline_ = std::move(loaded->timeline);
    effective_ = loaded->effective;
    next_ = nextEvent_ = 0;
    finishedSignalled_ = false;
    anchorPos_ = 0;
    emit openingProgress(100);
    setState(State::Open);
    restartClock();
    if (!paused_) timer_.start();
}

void ReplayTransport::close() {
    stopLoader();
    timer_.stop();
    setState(State::Closed);
}

QString ReplayTransport::description() const {
    return tr("replay of %1").arg(QFileInfo(path_).fileName());
}

QString ReplayTransport::readOnlyReason() const {
    return tr("a recorded log cannot take commands");
}

bool ReplayTransport::buildTimeline(const Recording &recording, Timing timing, Timing &effective,
                                    std::vector<Slice> &timeline, const std::atomic<bool> &cancel,
                                    const std::function<void(int)> &progress) {
    timeline.clear();
    effective = timing == Timing::Auto
                        ? (recording.hasIndex ? Timing::HostTime : Timing::SentenceTime)
                        : timing;
    if (effective == Timing::HostTime) {
        const qint64 t0 = recording.chunks.empty() ? 0 : recording.chunks.front().hostMs;
        for (const auto &c : recording.chunks)
            timeline.push_back({std::max(0.0, (c.hostMs - t0) / 1000.0), c.offset, c.length});
        return true;
    }
    // Lines timed by the last sentence time seen (the first one for lines before it); the lines
    // of one time are one slice (an epoch's sentences arrive together).
    const QByteArray &b = recording.bytes;
    const qint64 size = b.size();
    double first = -1, last = -1, dayOffset = 0;
    qint64 start = 0;
    int lines = 0;
    auto add = [&](double at, qint64 offset, qint64 length) {
        if (!timeline.empty() && timeline.back().t == at &&
            timeline.back().offset + timeline.back().length == offset &&
            timeline.back().length < kMaxSliceBytes)
            timeline.back().length += length;
        else
            timeline.push_back({at, offset, length});
    };
    while (start < size) {
        if (++lines % 4096 == 0) {
            if (cancel.load(std::memory_order_relaxed)) return false;
            progress(static_cast<int>(start * 100 / size));
        }
        qint64 end = b.indexOf('\n', start);
        end = end < 0 ? size : end + 1;
        std::string_view text(b.constData() + start, static_cast<std::size_t>(end - start));
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
        const auto dollar = text.find_first_of("$!");
        double t = effective == Timing::AsFast || dollar == std::string_view::npos
                           ? -1
                           : sentenceTime(text.substr(dollar));
        if (t >= 0) {
            if (first < 0) first = t;
            t += dayOffset;
            if (last >= 0 && t < last - 43200) { // past midnight
                dayOffset += 86400;
                t += 86400;
            }
            if (last >= 0 && t < last) t = last; // out of order: never go back in time
            last = t;
        }
        add(last >= 0 ? last - first : 0, start, end - start);
        start = end;
    }
    return true;
}

double ReplayTransport::duration() const {
    return timeline_.empty() ? 0 : timeline_.back().t;
}

double ReplayTransport::position() const {
    if (paused_ || state() != State::Open) return anchorPos_;
    return std::min(duration(), anchorPos_ + clock_.elapsed() / 1000.0 * speed_);
}

void ReplayTransport::restartClock() {
    clock_.start();
}

void ReplayTransport::setSpeed(double factor) {
    if (!(factor > 0)) return;
    anchorPos_ = position();
    restartClock();
    speed_ = factor;
}

void ReplayTransport::pause() {
    if (paused_) return;
    anchorPos_ = position();
    paused_ = true;
    timer_.stop();
}

void ReplayTransport::resume() {
    if (!paused_) return;
    paused_ = false;
    restartClock();
    if (state() == State::Open) timer_.start();
}

bool ReplayTransport::step() {
    pause();
    if (atEnd()) return false;
    const double t = timeline_[next_].t;
    std::size_t end = next_;
    while (end < timeline_.size() && timeline_[end].t == t) ++end;
    anchorPos_ = t;
    deliverUpTo(end);
    return true;
}

void ReplayTransport::seek(double seconds) {
    seconds = std::clamp(seconds, 0.0, duration());
    next_ = static_cast<std::size_t>(
            std::lower_bound(timeline_.begin(), timeline_.end(), seconds,
                             [](const Slice &s, double v) { return s.t < v; }) -
            timeline_.begin());
    const qint64 offset = next_ < timeline_.size() ? timeline_[next_].offset
                                                   : static_cast<qint64>(recording_.bytes.size());
    nextEvent_ = 0;
    while (nextEvent_ < recording_.events.size() && recording_.events[nextEvent_].offset < offset)
        ++nextEvent_;
    anchorPos_ = seconds;
    finishedSignalled_ = false;
    restartClock();
    if (!paused_ && state() == State::Open) timer_.start();
}

void ReplayTransport::tick() {
    if (state() != State::Open) return timer_.stop();
    const double now = effective_ == Timing::AsFast ? duration() + 1 : position();
    std::size_t end = next_;
    qint64 bytes = 0;
    while (end < timeline_.size() && timeline_[end].t <= now && bytes < kMaxBytesPerTick)
        bytes += timeline_[end++].length;
    deliverUpTo(end);
}

void ReplayTransport::deliverUpTo(std::size_t end) {
    if (end > next_) {
        const qint64 from = timeline_[next_].offset;
        const qint64 to = timeline_[end - 1].offset + timeline_[end - 1].length;
        next_ = end;
        // Events recorded before the first byte delivered now come first.
        while (nextEvent_ < recording_.events.size() &&
               recording_.events[nextEvent_].offset <= from)
            emit recordedEvent(recording_.events[nextEvent_++]);
        emit bytesReceived(recording_.bytes.mid(from, to - from));
        while (nextEvent_ < recording_.events.size() && recording_.events[nextEvent_].offset < to)
            emit recordedEvent(recording_.events[nextEvent_++]);
    }
    if (atEnd() && !finishedSignalled_) {
        while (nextEvent_ < recording_.events.size())
            emit recordedEvent(recording_.events[nextEvent_++]);
        finishedSignalled_ = true;
        timer_.stop();
        emit finished();
    }
}

} // namespace gnss::link
