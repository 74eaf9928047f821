#include "link/command_queue.h"

#include "link/sentence_stream.h"

#include "core/baud_rates.h"

#include "core/sentence_builder.h"
#include "link/transport.h"

#include <array>

namespace gnss::link {

namespace {

// A standard query, $ttllQ,sss (NMEA 0183 "query sentence"), is answered by sentence sss.
ReplyVerdict classifyStandardQuery(const Sentence &command, const Sentence &reply,
                                   ReplyProgress &) {
    const auto wanted = command.field(0);
    if (reply.address() == wanted) return ReplyVerdict::Accepted;
    if (!reply.proprietary() && reply.type() == wanted) return ReplyVerdict::Accepted;
    return ReplyVerdict::NotMine;
}

constexpr ReplyRule kStandardQueryRule{
        "",
        "",
        classifyStandardQuery,
        1000,
        2,
        CommandEffect::None,
        "the sentence named in the query ($GPGPQ,GGA -> $GPGGA,...)"};

bool isStandardQuery(const Sentence &s) {
    const auto a = s.address();
    return !s.proprietary() && a.size() == 5 && a.back() == 'Q' && s.fieldCount() >= 1;
}

} // namespace

QString outcomeName(CommandOutcome outcome) {
    switch (outcome) {
    case CommandOutcome::Accepted: return CommandQueue::tr("accepted");
    case CommandOutcome::Refused: return CommandQueue::tr("refused");
    case CommandOutcome::TimedOut: return CommandQueue::tr("timed out");
    case CommandOutcome::LinkLost: return CommandQueue::tr("link lost");
    case CommandOutcome::Cancelled: return CommandQueue::tr("cancelled");
    case CommandOutcome::Sent: return CommandQueue::tr("sent");
    case CommandOutcome::Failed: return CommandQueue::tr("failed");
    }
    return {};
}

QString lengthRefusal(std::string_view line, const Dialect &dialect) {
    const std::size_t n = line.size() + 2; // with "\r\n"
    if (n <= dialect.maxSentenceLength) return {};
    return CommandQueue::tr("Too long: %1 characters with its line end; %2 takes at most %3")
            .arg(n)
            .arg(QString::fromUtf8(dialect.displayName.data(),
                                   qsizetype(dialect.displayName.size())))
            .arg(dialect.maxSentenceLength);
}

CommandQueue::CommandQueue(Transport *transport, SentenceStream *stream, QObject *parent)
    : QObject(parent), transport_(transport), stream_(stream) {
    timer_.setSingleShot(true);
    connect(&timer_, &QTimer::timeout, this, &CommandQueue::onTimeout);
    if (stream) connect(stream, &SentenceStream::sentenceDecoded, this, &CommandQueue::onEvent);
    if (transport) {
        connect(transport, &Transport::stateChanged, this, [this](Transport::State s) {
            if (s == Transport::State::Open)
                startNext(); // commands queued while the link was being opened
            else if (s != Transport::State::Connecting)
                onLinkDown();
        });
    }
}

CommandQueue::~CommandQueue() = default;

int CommandQueue::enqueue(const QString &typed, const CommandOptions &options, QString *error) {
    std::string why;
    std::string line = completeSentence(typed.toStdString(), why);
    if (line.empty()) {
        if (error)
            *error =
                    tr("Not a sentence: %1 (%2)").arg(typed.trimmed(), QString::fromStdString(why));
        return -1;
    }
    if (dialect_) {
        if (const QString tooLong = lengthRefusal(line, *dialect_); !tooLong.isEmpty()) {
            if (error) *error = tooLong;
            return -1;
        }
    }
    const int id = nextId_++;
    queue_.push_back({id, std::move(line), options});
    if (!isBusy()) QMetaObject::invokeMethod(this, &CommandQueue::startNext, Qt::QueuedConnection);
    return id;
}

bool CommandQueue::cancel(int id) {
    if (current_ && current_->id == id) {
        finish(CommandOutcome::Cancelled, tr("cancelled before the receiver answered"));
        return true;
    }
    for (auto it = queue_.begin(); it != queue_.end(); ++it) {
        if (it->id != id) continue;
        CommandResult r;
        r.id = id;
        r.sentence = QString::fromStdString(it->line);
        r.outcome = CommandOutcome::Cancelled;
        r.detail = tr("cancelled before it was sent");
        queue_.erase(it);
        conclude(r);
        return true;
    }
    return false;
}

void CommandQueue::cancelAll() {
    while (!queue_.empty()) cancel(queue_.back().id);
    if (current_) cancel(current_->id);
}

const ReplyRule *CommandQueue::findRule(std::span<const ReplyRule> rules, const Sentence &command) {
    const ReplyRule *any = nullptr;
    for (const ReplyRule &r : rules) {
        if (r.commandAddress != command.address()) continue;
        if (r.firstField.empty()) {
            if (!any) any = &r;
        } else if (r.firstField == command.field(0)) {
            return &r;
        }
    }
    return any;
}

const ReplyRule *CommandQueue::ruleFor(const Sentence &command) const {
    if (dialect_)
        if (const ReplyRule *r = findRule(dialect_->replyRules, command)) return r;
    for (const Dialect *d : others_)
        if (const ReplyRule *r = findRule(d->replyRules, command)) return r;
    if (isStandardQuery(command)) return &kStandardQueryRule;
    return nullptr;
}

void CommandQueue::startNext() {
    if (isBusy() || queue_.empty()) return;
    // A link still being opened (a TCP connect): the commands wait for it, in order.
    if (transport_ && transport_->isConnecting()) return;
    current_ = std::move(queue_.front());
    queue_.pop_front();
    command_.parse(current_->line);
    rule_ = ruleFor(command_);
    progress_ = {};
    phase_ = Phase::Waiting;
    result_ = {};
    result_.id = current_->id;
    result_.sentence = QString::fromStdString(current_->line);
    elapsed_.start();
    if (!transport_ || !transport_->isOpen()) {
        finish(CommandOutcome::LinkLost, tr("not connected: the command was not sent"));
        return;
    }
    if (!transport_->canWrite()) {
        const QString why = transport_->readOnlyReason();
        finish(CommandOutcome::Failed,
               why.isEmpty() ? tr("%1 cannot send commands").arg(transport_->description()) : why);
        return;
    }
    sendCurrent();
}

void CommandQueue::sendCurrent() {
    ++result_.attempts;
    progress_ = {};
    result_.replies.clear();
    const QByteArray bytes = QByteArray::fromStdString(current_->line) + "\r\n";
    const int id = current_->id;
    const int attempts = result_.attempts;
    const QString sentence = result_.sentence;
    if (!transport_->write(bytes)) {
        finish(CommandOutcome::Failed,
               tr("could not write to %1: %2")
                       .arg(transport_->description(), transport_->errorString()));
        return;
    }
    emit commandSent(id, sentence, attempts);
    // A transport may hand over the answer within write() (the tests' fake one does): then the
    // command is finished already and current_ is empty.
    if (!current_) return;
    if (!rule_ || !rule_->classify) {
        const bool baud = rule_ && rule_->effect == CommandEffect::ChangesBaud;
        if (baud && transport_->baud() > 0 && baudFromCommand() > 0) return beginBaudSwitch(200);
        finish(CommandOutcome::Sent, rule_ ? tr("sent; the receiver does not answer this command")
                                           : tr("sent; no known reply to wait for"));
        return;
    }
    const int timeout =
            current_->options.timeoutMs >= 0 ? current_->options.timeoutMs : rule_->timeoutMs;
    timer_.start(std::max(timeout, 1));
}

void CommandQueue::onEvent(const SentenceEvent &event) {
    if (!current_ || phase_ == Phase::PreSwitch) return;
    const Sentence &reply = event.sentence;
    const std::string_view line = reply.line();
    const bool checksumOk =
            reply.checksum() == ChecksumStatus::Ok ||
            (reply.checksum() == ChecksumStatus::Missing && dialect_ && dialect_->checksumOptional);
    if (!checksumOk) return;

    if (phase_ == Phase::SwitchingBaud || phase_ == Phase::FallingBack) {
        // Any valid sentence proves the line works at the speed now set.
        timer_.stop();
        if (phase_ == Phase::SwitchingBaud) {
            result_.baudAfter = targetBaud_;
            finish(CommandOutcome::Accepted,
                   tr("the port now runs at %1 baud; the receiver talks at that rate")
                           .arg(targetBaud_));
        } else {
            result_.baudAfter = result_.baudBefore;
            finish(CommandOutcome::Failed,
                   tr("no valid data at %1 baud after the change; the receiver still talks at "
                      "%2 baud, so the port is back at %2")
                           .arg(targetBaud_)
                           .arg(result_.baudBefore));
        }
        return;
    }
    if (!rule_ || !rule_->classify) return;
    const ReplyVerdict v = rule_->classify(command_, reply, progress_);
    if (v == ReplyVerdict::NotMine) return;
    const QString text = QString::fromLatin1(line.data(), static_cast<qsizetype>(line.size()));
    result_.replies.append(text);
    emit replyReceived(current_->id, text);
    emit replyDecoded(current_->id, event);
    switch (v) {
    case ReplyVerdict::Partial: timer_.start(); break; // more to come: the timeout starts again
    case ReplyVerdict::Accepted:
        timer_.stop();
        if (rule_->effect == CommandEffect::ChangesBaud && transport_->baud() > 0 &&
            baudFromCommand() > 0)
            return beginBaudSwitch(0);
        finish(CommandOutcome::Accepted, tr("accepted"));
        break;
    case ReplyVerdict::Refused:
        timer_.stop();
        finish(CommandOutcome::Refused, tr("the receiver refused it: %1").arg(text));
        break;
    case ReplyVerdict::NotMine: break;
    }
}

int CommandQueue::baudFromCommand() const {
    if (!current_) return 0;
    if (current_->options.newBaud > 0) return current_->options.newBaud;
    int found = 0;
    for (std::size_t i = 0; i < command_.fieldCount(); ++i) {
        const auto f = command_.field(i);
        for (int b : kStandardBauds) {
            if (f == std::to_string(b)) {
                if (found) return 0; // two candidates: do not guess
                found = b;
            }
        }
    }
    return found;
}

void CommandQueue::beginBaudSwitch(int delayMs) {
    targetBaud_ = baudFromCommand();
    result_.baudBefore = transport_->baud();
    phase_ = Phase::PreSwitch;
    if (targetBaud_ == result_.baudBefore) {
        result_.baudAfter = targetBaud_;
        finish(CommandOutcome::Accepted, tr("accepted; the speed was already %1").arg(targetBaud_));
        return;
    }
    // A command without a reply may still be in the UART: let it out at the old speed first.
    const int id = current_->id;
    QTimer::singleShot(delayMs, this, [this, id] {
        if (!current_ || current_->id != id || phase_ != Phase::PreSwitch) return;
        phase_ = Phase::SwitchingBaud;
        // Timer first: an answer to the probe within switchTo() finishes the command (and stops
        // it), leaving current_ empty.
        timer_.start(current_->options.confirmMs);
        switchTo(targetBaud_);
    });
}

void CommandQueue::switchTo(int baud) {
    transport_->setBaud(baud);
    transport_->discardInput();
    if (stream_) stream_->resetFraming();
    emit baudChanged(baud);
    // A receiver with its output off still answers its probe: ask for traffic.
    if (dialect_ && !dialect_->probeCommand.empty())
        transport_->write(QByteArray(dialect_->probeCommand.data(),
                                     static_cast<qsizetype>(dialect_->probeCommand.size())) +
                          "\r\n");
}

void CommandQueue::onTimeout() {
    if (!current_) return;
    if (phase_ == Phase::SwitchingBaud) {
        phase_ = Phase::FallingBack;
        timer_.start(current_->options.confirmMs); // first, as above
        switchTo(result_.baudBefore);
        return;
    }
    if (phase_ == Phase::FallingBack) {
        result_.baudAfter = 0;
        finish(CommandOutcome::LinkLost,
               tr("no valid data at %1 baud after the change, nor back at %2 baud: check the "
                  "receiver and the cable, then detect the baud rate again")
                       .arg(targetBaud_)
                       .arg(result_.baudBefore));
        return;
    }
    const int retries = current_->options.retries >= 0 ? current_->options.retries : rule_->retries;
    if (result_.attempts <= retries) {
        sendCurrent();
        return;
    }
    finish(CommandOutcome::TimedOut,
           tr("no answer after %n attempt(s)", nullptr, result_.attempts));
}

void CommandQueue::onLinkDown() {
    if (!current_ && queue_.empty()) return;
    const QString why = transport_ ? transport_->errorString() : QString();
    if (current_)
        finish(CommandOutcome::LinkLost,
               why.isEmpty() ? tr("the link closed before the answer")
                             : tr("the link was lost before the answer: %1").arg(why));
    // The rest were meant to run after it, in order: none of them is sent.
    while (!queue_.empty()) {
        CommandResult r;
        r.id = queue_.front().id;
        r.sentence = QString::fromStdString(queue_.front().line);
        r.outcome = CommandOutcome::LinkLost;
        r.detail = tr("not sent: the link was lost");
        queue_.pop_front();
        conclude(r);
    }
}

void CommandQueue::conclude(const CommandResult &r) {
    history_.append(r);
    if (history_.size() > kHistoryLimit) history_.removeFirst();
    emit commandFinished(r);
}

void CommandQueue::finish(CommandOutcome outcome, const QString &detail) {
    if (!current_) return;
    timer_.stop();
    result_.outcome = outcome;
    result_.detail = detail;
    result_.elapsedMs = elapsed_.elapsed();
    const CommandResult r = result_;
    current_.reset();
    rule_ = nullptr;
    phase_ = Phase::Waiting;
    conclude(r);
    if (!queue_.empty())
        QMetaObject::invokeMethod(this, &CommandQueue::startNext, Qt::QueuedConnection);
    else if (!current_)
        emit idle();
}

} // namespace gnss::link
