#include "models/compare_model.h"

#include "compare/comparison_json.h"
#include "core/json_writer.h"
#include "models/receiver_state_model.h"

#include <cstdio>

namespace gnss::ui {

namespace {
constexpr std::int64_t kCompareDayMs = 86'400'000;
constexpr int kCompareTickMs = 500;

QString timeOfDay(std::int64_t ms) {
    return QStringLiteral("%1:%2:%3.%4")
            .arg(ms / 3'600'000, 2, 10, QLatin1Char('0'))
            .arg(ms / 60'000 % 60, 2, 10, QLatin1Char('0'))
            .arg(ms / 1000 % 60, 2, 10, QLatin1Char('0'))
            .arg(ms % 1000, 3, 10, QLatin1Char('0'));
}

QString fixName(FixType f) {
    const std::string_view n = toString(f);
    return QString::fromLatin1(n.data(), qsizetype(n.size()));
}

QString number(const std::optional<double> &v, int decimals) {
    return v ? QString::number(*v, 'f', decimals) : QString();
}
} // namespace

CompareModel::CompareModel(QObject *parent) : QObject(parent) {
    tick_.setInterval(kCompareTickMs);
    connect(&tick_, &QTimer::timeout, this, [this] {
        if (!dirty_) return;
        dirty_ = false;
        emit changed();
    });
    tick_.start();
}

CompareModel::~CompareModel() = default;

std::vector<std::string> CompareModel::names() const {
    std::vector<std::string> out;
    for (const Receiver &r : receivers_) out.push_back(r.name.toStdString());
    return out;
}

void CompareModel::setReceivers(const QList<Receiver> &receivers) {
    for (const auto &c : std::as_const(connections_)) disconnect(c);
    connections_.clear();
    receivers_ = receivers;
    comparison_ = std::make_unique<compare::Comparison>(names());
    latest_.assign(std::size_t(receivers_.size()), std::nullopt);
    matches_.clear();
    report_.reset();
    for (int i = 0; i < receivers_.size(); ++i)
        if (receivers_[i].state)
            connections_ << connect(receivers_[i].state, &ReceiverStateModel::updated, this,
                                    [this, i] { observe(i); });
    dirty_ = true;
}

void CompareModel::setName(int receiver, const QString &name) {
    if (receiver < 0 || receiver >= receivers_.size() || receivers_[receiver].name == name) return;
    receivers_[receiver].name = name;
    comparison_->setName(std::size_t(receiver), name.toStdString());
    report_.reset();
    dirty_ = true;
}

void CompareModel::setWindowSeconds(int seconds) {
    windowSeconds_ = qMax(1, seconds);
    evict();
    report_.reset();
    dirty_ = true;
}

void CompareModel::observe(int receiver) {
    if (receivers_.size() < 2) return; // nothing to compare: no work per epoch
    const ReceiverStateModel *state = receivers_[receiver].state;
    if (!state || state->epochCount() == 0) return; // cleared: a new connection
    auto o = compare::Observation::of(state->state().epoch);
    if (!o) return;
    latest_[std::size_t(receiver)] = *o;
    comparison_->add(std::size_t(receiver), std::move(*o), [this](const compare::Match &m) {
        matches_.push_back(compare::MatchRecord::of(m));
        evict();
        report_.reset();
        dirty_ = true;
    });
}

void CompareModel::evict() {
    if (matches_.empty()) return;
    const std::int64_t newest = matches_.back().timeMs;
    const std::int64_t span = std::int64_t(windowSeconds_) * 1000;
    // Ages past midnight count on from the day before.
    auto age = [newest](std::int64_t t) { return (newest - t + kCompareDayMs) % kCompareDayMs; };
    while (!matches_.empty() && age(matches_.front().timeMs) > span) matches_.pop_front();
}

const compare::Report &CompareModel::report() const {
    if (!report_) report_ = compare::Comparison::reportOf(names(), matches_);
    return *report_;
}

std::size_t CompareModel::matchedEpochs() const {
    return comparison_ ? comparison_->matchedEpochs() : 0;
}

const compare::Observation *CompareModel::latest(int receiver) const {
    if (receiver < 0 || std::size_t(receiver) >= latest_.size() || !latest_[receiver])
        return nullptr;
    return &*latest_[std::size_t(receiver)];
}

QByteArray CompareModel::csv() const {
    QByteArray out = "time,receiver,fix,reference_fix,east_m,north_m,up_m,horizontal_m,"
                     "cn0_mean_db,signals_compared,only_in_reference,only_in_this\n";
    for (const compare::MatchRecord &m : matches_) {
        for (std::size_t i = 0; i < m.differences.size(); ++i) {
            const compare::Difference &d = m.differences[i];
            double sum = 0;
            for (const auto &p : d.cn0) sum += p.other - p.reference;
            QString name = receivers_.value(int(i + 1)).name;
            name.replace('"', QLatin1String("\"\""));
            const QStringList row{
                    timeOfDay(m.timeMs),
                    QStringLiteral("\"%1\"").arg(name),
                    fixName(m.fixes.at(i + 1)),
                    fixName(m.fixes.at(0)),
                    number(d.east, 3),
                    number(d.north, 3),
                    number(d.up, 3),
                    number(d.horizontal, 3),
                    d.cn0.empty() ? QString() : QString::number(sum / double(d.cn0.size()), 'f', 2),
                    QString::number(d.cn0.size()),
                    QString::number(d.onlyInReference.size()),
                    QString::number(d.onlyInOther.size())};
            out += row.join(',').toUtf8() + '\n';
        }
    }
    return out;
}

QByteArray CompareModel::json() const {
    std::string s;
    JsonWriter w(s);
    compare::writeReportJson(w, report());
    return QByteArray::fromStdString(s) + '\n';
}

} // namespace gnss::ui
