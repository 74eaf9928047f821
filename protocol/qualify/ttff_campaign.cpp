#include "qualify/ttff_campaign.h"

#include "core/sentence_builder.h"
#include "link/connection.h"
#include "state/epoch.h"
#include "state/epoch_assembler.h"

namespace gnss::qualify {

namespace {

const ActionDef *actionOf(const Dialect *d, ReceiverAction a) {
    if (!d) return nullptr;
    for (const ActionDef &x : d->actions)
        if (x.action == a) return &x;
    return nullptr;
}

QString startName(ReceiverAction a) {
    return QString::fromLatin1(toString(a).data(), qsizetype(toString(a).size()));
}

} // namespace

QString TtffCampaign::refusal(const Dialect *dialect, const std::vector<ReceiverAction> &starts) {
    if (!dialect) return tr("the receiver's dialect is not known: no restart command to send");
    QStringList has, lacks;
    for (ReceiverAction a :
         {ReceiverAction::ColdStart, ReceiverAction::WarmStart, ReceiverAction::HotStart})
        if (actionOf(dialect, a)) has << startName(a);
    for (ReceiverAction a : starts)
        if (!actionOf(dialect, a)) lacks << startName(a);
    if (lacks.isEmpty()) return {};
    return tr("%1 has no %2 start (it has: %3)")
            .arg(QString::fromLatin1(dialect->displayName.data(),
                                     qsizetype(dialect->displayName.size())),
                 lacks.join(QStringLiteral(", ")),
                 has.isEmpty() ? tr("none") : has.join(QStringLiteral(", ")));
}

TtffCampaign::TtffCampaign(link::Connection *connection, const Dialect *dialect, Plan plan,
                           QObject *parent)
    : QObject(parent), connection_(connection), dialect_(dialect), plan_(std::move(plan)),
      assembler_(std::make_unique<EpochAssembler>(dialect)) {
    connect(connection_->stream(), &link::SentenceStream::sentenceDecoded, this,
            &TtffCampaign::onSentence);
    connect(connection_->commands(), &link::CommandQueue::commandSent, this,
            [this](int id, const QString &, int attempt) {
                if (id != commandId_ || attempt != 1 || phase_ != Phase::Restarting) return;
                sinceCommand_.start(); // the run's clock: the restart is written
                tracker_.emplace(plan_.starts[startIndex_], runIndex_);
                if (plan_.reference)
                    tracker_->setReference(plan_.reference->first, plan_.reference->second);
                phase_ = Phase::Running;
                say();
            });
    // A run the link drops in is lost; one not begun yet (waiting for its held fix) is run again
    // once the link is back, after the pause.
    connect(connection_, &link::Connection::linkLost, this, [this] {
        if (phase_ == Phase::Running || phase_ == Phase::Restarting)
            endRun(RunOutcome::Lost);
        else if (phase_ == Phase::Settling || phase_ == Phase::Ready)
            --runIndex_;
        if (phase_ != Phase::Done && phase_ != Phase::Idle) {
            phase_ = Phase::WaitingForLink;
            say();
        }
    });
    connect(connection_, &link::Connection::linkRestored, this, [this] {
        if (phase_ != Phase::WaitingForLink) return;
        fixNow_ = false;
        phase_ = Phase::Pausing;
        inPhase_.start();
        say();
    });
    tick_.setInterval(100);
    connect(&tick_, &QTimer::timeout, this, &TtffCampaign::tick);
}

TtffCampaign::~TtffCampaign() = default;

void TtffCampaign::start() {
    runs_.clear();
    startIndex_ = 0;
    runIndex_ = 0;
    cancelled_ = false;
    if (plan_.starts.empty() || plan_.runs <= 0) {
        phase_ = Phase::Done;
        emit finished(false);
        return;
    }
    tick_.start();
    nextRun();
}

void TtffCampaign::cancel() {
    if (phase_ == Phase::Done) return;
    cancelled_ = true;
    if (commandId_ >= 0) connection_->commands()->cancel(commandId_);
    tick_.stop();
    phase_ = Phase::Done;
    say();
    emit finished(true);
}

void TtffCampaign::nextRun() {
    if (runIndex_ >= plan_.runs) {
        runIndex_ = 0;
        ++startIndex_;
    }
    if (startIndex_ >= plan_.starts.size()) {
        tick_.stop();
        phase_ = Phase::Done;
        say();
        emit finished(false);
        return;
    }
    ++runIndex_;
    // A warm or hot start needs the ephemerides a held fix brings; a cold one drops them anyway.
    phase_ = plan_.starts[startIndex_] == ReceiverAction::ColdStart ? Phase::Restarting
                                                                    : Phase::Settling;
    inPhase_.start();
    if (phase_ == Phase::Restarting) restartOrWait();
    say();
}

void TtffCampaign::restartOrWait() {
    if (!barrier_) {
        phase_ = Phase::Restarting;
        restart();
        return;
    }
    phase_ = Phase::Ready;
    inPhase_.start();
    say();
    emit readyToRestart();
}

void TtffCampaign::go() {
    if (phase_ != Phase::Ready) return;
    phase_ = Phase::Restarting;
    inPhase_.start();
    restart();
    say();
}

void TtffCampaign::restart() {
    const ActionDef *a = actionOf(dialect_, plan_.starts[startIndex_]);
    link::CommandOptions o;
    o.retries = 0; // sent twice, it would restart twice
    o.timeoutMs = 1000;
    commandId_ =
            a ? connection_->commands()->enqueue(QString::fromStdString(buildSentence(a->body)), o)
              : -1;
    if (commandId_ < 0) endRun(RunOutcome::Lost);
}

void TtffCampaign::onSentence(const SentenceEvent &ev) {
    if (!ev.message) return;
    assembler_->setDialect(connection_->stream()->dialect());
    assembler_->add(ev.sentence, *ev.message, [this](const Epoch &e) { onEpoch(e); });
}

void TtffCampaign::onEpoch(const Epoch &e) {
    const bool fix3d = e.fix >= FixType::Fix3D && e.fix <= FixType::RtkFixed && e.lat && e.lon;
    if (fix3d && !fixNow_) fixHeld_.start();
    fixNow_ = fix3d;
    emit epoch(e);
    if (phase_ != Phase::Running || !tracker_) return;
    tracker_->add(e, double(sinceCommand_.nsecsElapsed()) / 1e9);
    if (tracker_->fixed3d()) endRun(RunOutcome::Fixed);
}

void TtffCampaign::endRun(RunOutcome outcome) {
    // A restart not yet written when the link went is not written when it comes back.
    if (commandId_ >= 0 && outcome != RunOutcome::Fixed)
        connection_->commands()->cancel(commandId_);
    if (!tracker_) tracker_.emplace(plan_.starts[startIndex_], runIndex_);
    tracker_->finish(outcome);
    runs_.push_back(tracker_->run());
    tracker_.reset();
    commandId_ = -1;
    emit runFinished(runs_.back());
    phase_ = Phase::Pausing;
    inPhase_.start();
    say();
}

void TtffCampaign::tick() {
    switch (phase_) {
    case Phase::Settling:
        if (fixNow_ && fixHeld_.isValid() && fixHeld_.elapsed() >= plan_.holdMs) restartOrWait();
        // No fix to hold within a run's limit: the run times out, its restart not sent (the
        // campaign goes on rather than waiting for a receiver that may never fix).
        else if (inPhase_.elapsed() >= plan_.timeoutMs)
            endRun(RunOutcome::TimedOut);
        break;
    case Phase::Ready:
        // The others did not become ready within a run's limit (one has no fix to hold): this
        // one restarts alone rather than wait for them.
        if (inPhase_.elapsed() >= plan_.timeoutMs) {
            phase_ = Phase::Restarting;
            restart();
        }
        break;
    case Phase::Running:
        if (sinceCommand_.elapsed() >= plan_.timeoutMs) endRun(RunOutcome::TimedOut);
        break;
    case Phase::Pausing:
        if (inPhase_.elapsed() >= plan_.pauseMs) nextRun();
        break;
    default: break;
    }
    if (phase_ != Phase::Done && inPhase_.isValid() && inPhase_.elapsed() % 1000 < 100) say();
}

QString TtffCampaign::stateText() const {
    if (phase_ == Phase::Done)
        return cancelled_ ? tr("Cancelled after %n run(s)", nullptr, int(runs_.size()))
                          : tr("Done: %n run(s)", nullptr, int(runs_.size()));
    const QString run =
            tr("%1 %2 of %3")
                    .arg(startName(plan_.starts[std::min(startIndex_, plan_.starts.size() - 1)]))
                    .arg(runIndex_)
                    .arg(plan_.runs);
    const double s = double(inPhase_.isValid() ? inPhase_.elapsed() : 0) / 1000.0;
    switch (phase_) {
    case Phase::Settling:
        return tr("%1: waiting for a 3D fix held %2 s (ephemerides), %3 s")
                .arg(run)
                .arg(plan_.holdMs / 1000)
                .arg(s, 0, 'f', 0);
    case Phase::Ready: return tr("%1: waiting for the other receivers").arg(run);
    case Phase::Restarting: return tr("%1: restarting").arg(run);
    case Phase::Running:
        return tr("%1: waiting for a 3D fix, %2 s")
                .arg(run)
                .arg(double(sinceCommand_.elapsed()) / 1000.0, 0, 'f', 1);
    case Phase::Pausing: return tr("%1: done, pausing").arg(run);
    case Phase::WaitingForLink: return tr("%1: link lost, waiting for it").arg(run);
    default: return {};
    }
}

void TtffCampaign::say() {
    emit progress(stateText());
}

} // namespace gnss::qualify
