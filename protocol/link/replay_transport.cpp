#include "replay_transport.h"

#include "core/sentence.h"

#include <QFileInfo>

#include <algorithm>

namespace gnss::link {

namespace {

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

} // namespace

ReplayTransport::ReplayTransport(QString path, Timing timing, QObject *parent)
    : Transport(parent), path_(std::move(path)), timing_(timing) {
    timer_.setInterval(10);
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &ReplayTransport::tick);
}

bool ReplayTransport::open() {
    QString error;
    if (!loadRecording(path_, recording_, error)) {
        fail(error, false);
        return false;
    }
    if (timing_ == Timing::HostTime && !recording_.hasIndex) {
        fail(tr("%1 has no timestamp index (%2): replay it with sentence times instead")
                     .arg(path_, indexPathFor(path_)),
             false);
        return false;
    }
    buildTimeline();
    next_ = nextEvent_ = 0;
    finishedSignalled_ = false;
    anchorPos_ = 0;
    setState(State::Open);
    restartClock();
    if (!paused_) timer_.start();
    return true;
}

void ReplayTransport::close() {
    timer_.stop();
    setState(State::Closed);
}

QString ReplayTransport::description() const {
    return tr("replay of %1").arg(QFileInfo(path_).fileName());
}

void ReplayTransport::buildTimeline() {
    timeline_.clear();
    effective_ = timing_ == Timing::Auto
                         ? (recording_.hasIndex ? Timing::HostTime : Timing::SentenceTime)
                         : timing_;
    if (effective_ == Timing::HostTime) {
        const qint64 t0 = recording_.chunks.empty() ? 0 : recording_.chunks.front().hostMs;
        for (const auto &c : recording_.chunks)
            timeline_.push_back({std::max(0.0, (c.hostMs - t0) / 1000.0), c.offset, c.length});
        return;
    }
    // One slice per line, timed by the last sentence time seen (the first one for lines before).
    const QByteArray &b = recording_.bytes;
    std::vector<std::pair<qint64, qint64>> lines;
    std::vector<double> times;
    qint64 start = 0;
    while (start < b.size()) {
        qint64 end = b.indexOf('\n', start);
        end = end < 0 ? b.size() : end + 1;
        lines.emplace_back(start, end - start);
        std::string_view text(b.constData() + start, static_cast<std::size_t>(end - start));
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
        const auto dollar = text.find_first_of("$!");
        times.push_back(effective_ == Timing::AsFast || dollar == std::string_view::npos
                                ? -1
                                : sentenceTime(text.substr(dollar)));
        start = end;
    }
    double first = -1, last = -1, dayOffset = 0;
    for (double t : times)
        if (t >= 0) {
            first = t;
            break;
        }
    for (std::size_t i = 0; i < lines.size(); ++i) {
        double t = times[i];
        if (t >= 0) {
            t += dayOffset;
            if (last >= 0 && t < last - 43200) { // past midnight
                dayOffset += 86400;
                t += 86400;
            }
            if (last >= 0 && t < last) t = last; // out of order: never go back in time
            last = t;
        }
        const double at = last >= 0 ? last - first : 0;
        timeline_.push_back({at, lines[i].first, lines[i].second});
    }
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
    while (end < timeline_.size() && timeline_[end].t <= now) ++end;
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
