#include "sim/receiver.h"

#include "nmea/nmea_rules.h"

#include <algorithm>
#include <cmath>

namespace gnss::sim {

namespace {

DecoderOptions decoderOptionsFor(const Dialect &d) {
    DecoderOptions o;
    o.dialect = std::string(d.id);
    return o;
}

} // namespace

Receiver::Receiver(const Dialect &dialect, const SimOptions &options)
    : Receiver(dialect, dialect.defaultBaud, options) {}

Receiver::Receiver(const Dialect &dialect, int defaultBaud, const SimOptions &options)
    : dialect_(dialect), options_(options), registry_(standardSentenceRules(), {&dialect}),
      decoder_(registry_, decoderOptionsFor(dialect)), sky_(options.seed, options.observer),
      faultRng_(options.seed ^ 0x5EED5EEDu), defaultBaud_(defaultBaud),
      baud_(options.baud > 0 ? options.baud : defaultBaud),
      ttffModel_(options.ttff.over(TtffModel::builtin())), ttffRng_(options.seed ^ 0x77FF0001u) {
    ttff_ = ttffModel_.draw(ResetKind::PowerCycle, ttffRng_);
    // The first epoch at power-on, on the UTC grid of epochs (whole seconds and their parts,
    // as real receivers): with a start of its own (startAfter), the first whole one after it.
    const double shift = std::fmod(options_.startAfter, 1.0);
    nextEpoch_ = shift > 1e-9 ? 1.0 - shift : 0.0;
    sky_.setNoise(options_.noise);
}

Receiver::~Receiver() = default;

void Receiver::receive(std::string_view bytes) {
    if (hungUp_ || baudMismatch() || poweredOff() || lineDropDue_) return;
    onHostBytes(bytes);
    decoder_.feed(bytes, [this](const SentenceEvent &ev) {
        // What follows the command that cut the power, or the line, is not heard.
        if (poweredOff() || lineDropDue_ || cutPowerAt(ev.sentence)) return;
        dropLineAt(ev.sentence);
        onCommand(ev.sentence, ev.message, ev.error);
    });
}

void Receiver::dropLineAt(const Sentence &command) {
    if (lineDropDone_ || !options_.faults.hangsUpOn(command.address(), command.field(0))) return;
    lineDropDone_ = true;
    lineDropDue_ = true;
}

bool Receiver::cutPowerAt(const Sentence &command) {
    const FaultSpec &f = options_.faults;
    if (powerCutDone_ || !f.cutsPower(command.address(), command.field(0))) return false;
    powerCutDone_ = true;
    offUntil_ = now_ + FaultSpec::kPowerCutSeconds;
    pending_.clear(); // replies not yet out, a baud switch to come: gone with the power
    return true;
}

void Receiver::advance(double seconds) {
    const double end = now_ + std::max(0.0, seconds);
    while (!hungUp_) {
        // Off (powercut): nothing happens until it boots, from its flash.
        const bool off = poweredOff();
        double next = off ? offUntil_ : nextEpoch_;
        for (const Pending &p : pending_) next = std::min(next, p.at);
        if (next > end + 1e-9) break; // (epoch grids are sums of 0.1, 0.2: allow rounding)
        now_ = std::max(now_, next);
        if (hangsUp()) break;
        if (off) {
            reset(ResetKind::PowerCycle);
            continue;
        }
        flushDue();
        if (nextEpoch_ <= now_) runEpoch();
    }
    now_ = end;
    if (hangsUp()) hungUp_ = true;
    flushDue();
}

bool Receiver::hangsUp() const {
    const FaultSpec &f = options_.faults;
    return f.hangupAfter >= 0 && !f.hangupRepeats() && now_ >= f.hangupAfter;
}

std::string Receiver::takeOutput() {
    std::size_t due = 0;
    while (due < delayed_.size() && delayed_[due].first <= now_ + 1e-9)
        out_ += delayed_[due++].second;
    delayed_.erase(delayed_.begin(), delayed_.begin() + static_cast<std::ptrdiff_t>(due));
    std::string s;
    s.swap(out_);
    return s;
}

std::string Receiver::takeOutput(int port) {
    auto it = otherPorts_.find(port);
    if (it == otherPorts_.end()) return {};
    std::string s;
    s.swap(it->second);
    return s;
}

void Receiver::sendBytes(std::string_view bytes, int port) {
    if (port != 0) {
        std::string &out = otherPorts_[port];
        out.append(bytes);
        if (out.size() > kTxBuffer * 16) out.erase(0, out.size() - std::size_t(kTxBuffer * 16));
        return;
    }
    if (hungUp_ || options_.faults.silentAt(now_)) return;
    if (takeLineTime(bytes.size(), true)) write(std::string(bytes));
}

FixKind Receiver::fixAfter(double seconds) const {
    return seconds >= ttff_ ? FixKind::Autonomous : FixKind::None;
}

void Receiver::setFamilyTtff(const TtffModel &family) {
    ttffModel_ = options_.ttff.over(family.over(TtffModel::builtin()));
    ttff_ = ttffModel_.draw(ResetKind::PowerCycle, ttffRng_);
}

void Receiver::reset(ResetKind kind) {
    ttff_ = ttffModel_.draw(kind, ttffRng_);
    trackingSince_ = now_;
    lastFix_ = FixKind::None;
    if (kind == ResetKind::PowerCycle) // a reply not yet out is lost with the power
        pending_.erase(std::remove_if(pending_.begin(), pending_.end(),
                                      [](const Pending &p) { return p.thenBaud == 0; }),
                       pending_.end());
    onReset(kind);
    rescheduleEpochs();
}

void Receiver::rescheduleEpochs() {
    nextEpoch_ = nextOnGrid();
}

double Receiver::nextOnGrid() const {
    // The next multiple of the interval in UTC strictly after now: epochs are aligned to the
    // time grid, also when the receiver started between two of its points (startAfter).
    const double dt = epochInterval();
    const double utc = now_ + options_.startAfter;
    return (std::floor(utc / dt + 1e-9) + 1) * dt - options_.startAfter;
}

void Receiver::runEpoch() {
    const FixKind want = fixAfter(now_ - trackingSince_);
    // The sky is a function of UTC: a later start sees it further on.
    last_ = sky_.update(now_ + options_.startAfter, useMask(), want,
                        trackingSince_ + options_.startAfter);
    applyDifferences(options_.differences, last_);
    lastFix_ = last_.fix;
    if (options_.faults.binary > 0) {
        std::uniform_real_distribution<double> u(0, 1);
        if (u(faultRng_) < options_.faults.binary) {
            static const int kNumbers[] = {1005, 1077, 1087, 1097, 1127, 1230};
            std::uniform_int_distribution<int> pick(0, 5), len(20, 180);
            const std::string frame =
                    rtcm3Frame(faultRng_, kNumbers[pick(faultRng_)], len(faultRng_));
            if (!options_.faults.silentAt(now_)) write(frame);
        }
    }
    if (options_.faults.junkPerSecond > 0 && !options_.faults.silentAt(now_)) {
        std::uniform_int_distribution<int> byte(0, 255);
        std::string junk(std::size_t(options_.faults.junkPerSecond * epochInterval()), '\0');
        for (char &c : junk) {
            const int b = byte(faultRng_);
            c = static_cast<char>(b == '$' || b == '!' ? '#' : b); // never a sentence's start
        }
        write(junk);
    }
    onEpoch(last_);
    nextEpoch_ = nextOnGrid();
}

void Receiver::flushDue() {
    // In order of time, then of arrival (stable).
    std::stable_sort(pending_.begin(), pending_.end(),
                     [](const Pending &a, const Pending &b) { return a.at < b.at; });
    while (!pending_.empty() && pending_.front().at <= now_ + 1e-9) {
        Pending p = std::move(pending_.front());
        pending_.erase(pending_.begin());
        if (!p.text.empty() && !options_.faults.silentAt(now_)) { // a hung receiver answers not
            takeLineTime(p.text.size() + 2, false);
            write(p.text + "\r\n");
        }
        if (p.thenBaud > 0) baud_ = p.thenBaud;
    }
}

void Receiver::send(const std::string &sentence) {
    if (hungUp_ || options_.faults.silentAt(now_)) return;
    std::string line = sentence;
    const FaultSpec &f = options_.faults;
    std::uniform_real_distribution<double> u(0, 1);
    if (f.badChecksum > 0 && u(faultRng_) < f.badChecksum && line.size() >= 3 &&
        line[line.size() - 3] == '*') {
        // Flip one bit of the checksum's low digit: still hex, never the right value.
        char &c = line.back();
        c = c == '0' ? '1' : (c == 'F' ? 'E' : static_cast<char>(c == '9' ? 'A' : c + 1));
    }
    if (!takeLineTime(line.size() + 2, true)) return; // more than the line speed carries
    if (f.truncate > 0 && u(faultRng_) < f.truncate && line.size() > 8) {
        std::uniform_int_distribution<std::size_t> cut(4, line.size() - 4);
        write(line.substr(0, cut(faultRng_))); // no terminator: the next '$' cuts it
        return;
    }
    write(line + "\r\n");
}

void Receiver::reply(const Sentence &command, const std::string &sentence, int thenBaud) {
    const FaultSpec &f = options_.faults;
    const bool suppressed = f.replySuppressed(command.address(), command.field(0));
    if (suppressed && thenBaud == 0) return;
    const double at = now_ + f.slowReplyMs / 1000.0;
    pending_.push_back({at, suppressed ? std::string() : sentence, thenBaud});
    flushDue();
}

bool Receiver::takeLineTime(std::size_t bytes, bool mayDrop) {
    if (baud_ <= 0) return true;
    const double cost = static_cast<double>(bytes) * 10.0 / baud_; // start + 8 data + stop
    const double start = std::max(lineFreeAt_, now_);
    if (mayDrop && start - now_ + cost > kTxBuffer * 10.0 / baud_) {
        ++dropped_;
        return false;
    }
    lineFreeAt_ = start + cost;
    return true;
}

void Receiver::write(std::string bytes) {
    if (hungUp_) return;
    if (baudMismatch()) {
        // What a UART at another speed makes of these bytes: about as many bytes as the ratio
        // of the speeds, framing garbage with no '$' in it.
        const double ratio = static_cast<double>(lineBaud_) / baud_;
        const auto n = static_cast<std::size_t>(std::max(1.0, std::round(bytes.size() * ratio)));
        bytes = garble(n);
    }
    if (options_.differences.latency > 0)
        delayed_.emplace_back(now_ + options_.differences.latency, std::move(bytes));
    else
        out_ += bytes;
}

std::string Receiver::garble(std::size_t n) {
    std::string g;
    g.reserve(n);
    std::uniform_int_distribution<int> byte(0, 255);
    for (std::size_t i = 0; i < n; ++i) {
        int b = byte(faultRng_);
        // Mostly high-bit and framing-error bytes (0x00, 0x80, 0xF8, 0xFF), never a sentence start.
        if (b < 0x80 && (b & 3) != 0) b |= 0x80;
        if (b == '$' || b == '!' || b == '\n' || b == '\r') b = 0xFF;
        g.push_back(static_cast<char>(b));
    }
    return g;
}

double Receiver::utcSecondOfDay() const {
    return std::fmod(kStartSecondOfDay + options_.startAfter + now_, 86400.0);
}

Date Receiver::utcDate() const {
    // Days after 2024-03-15 (enough for simulations of days or weeks).
    int days = static_cast<int>(
            std::floor((kStartSecondOfDay + options_.startAfter + now_) / 86400.0));
    Date d{2024, 3, 15};
    static const int kMonthDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31}; // 2024
    while (days-- > 0) {
        if (++d.day > kMonthDays[(d.month - 1) % 12]) {
            d.day = 1;
            if (++d.month > 12) {
                d.month = 1;
                ++d.year;
            }
        }
    }
    return d;
}

double Receiver::gpsTimeOfWeek() const {
    // 2024-03-15 is a Friday (day 5 of the GPS week); GPS week 2305.
    return std::fmod(5 * 86400.0 + kStartSecondOfDay + options_.startAfter + now_ + kLeapSeconds,
                     604800.0);
}

int Receiver::gpsWeek() const {
    return 2305 + static_cast<int>((5 * 86400.0 + kStartSecondOfDay + options_.startAfter + now_ +
                                    kLeapSeconds) /
                                   604800.0);
}

} // namespace gnss::sim
