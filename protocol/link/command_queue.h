#pragma once
// CommandQueue: commands to the receiver, one at a time, each with a known outcome.
//
// Each command is matched to its dialect's ReplyRule (address, first field); received sentences
// are classified by the rule until one accepts or refuses it. No answer within the rule's
// timeout → sent again, up to the rule's retry count, then "timed out". A rule without a reply
// (classify == nullptr) counts as sent once written. A command that changes the port speed is
// followed through: reply, switch the port, confirm valid traffic at the new rate, or fall back
// to the old rate and say what happened. Losing the link fails the command in flight and every
// command queued behind it (they were meant to run in order).
#include "core/dialect.h"
#include "core/sentence.h"
#include "core/stream_decoder.h"

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <deque>
#include <vector>

namespace gnss::link {

class Transport;
class SentenceStream;

enum class CommandOutcome {
    Accepted,  // the receiver answered yes (or confirmed the new baud)
    Refused,   // the receiver answered no: its words are in `replies`
    TimedOut,  // no answer after every retry
    LinkLost,  // the link went away before the answer (or before sending)
    Cancelled, // cancelled by the user
    Sent,      // written; the receiver gives no answer to this command
    Failed,    // could not be written, or the follow-up (baud switch) failed: see `detail`
};

QString outcomeName(CommandOutcome outcome);

// Why `line` (a complete sentence, without its "\r\n") is too long for a receiver of `dialect`
// (its maxSentenceLength, line end included); empty when it fits.
QString lengthRefusal(std::string_view line, const Dialect &dialect);

struct CommandOptions {
    int timeoutMs = -1; // -1: the rule's
    int retries = -1;   // -1: the rule's
    // For a command that changes the port speed: the speed it sets. 0: read from the command
    // (the one field that is a standard baud rate), or no switch when there is none.
    int newBaud = 0;
    int confirmMs = 2500; // how long to wait for valid traffic after a switch
};

struct CommandResult {
    int id = 0;
    QString sentence; // as sent, without CR LF
    CommandOutcome outcome = CommandOutcome::Sent;
    QStringList replies; // the receiver's sentences that answered it
    QString detail;      // what happened, in words (for the status bar and the console)
    int attempts = 0;
    qint64 elapsedMs = 0;
    int baudBefore = 0, baudAfter = 0; // for baud changes
};

class CommandQueue : public QObject {
    Q_OBJECT
public:
    // Commands are written to `transport`; replies are read from `stream`, the link's one
    // decoder (the queue decodes nothing itself).
    CommandQueue(Transport *transport, SentenceStream *stream, QObject *parent = nullptr);
    ~CommandQueue() override;

    // The dialect whose reply rules apply first; `others` are searched when it has no rule for
    // a command (e.g. before the dialect is known).
    void setDialect(const Dialect *dialect) { dialect_ = dialect; }
    void setOtherDialects(std::vector<const Dialect *> others) { others_ = std::move(others); }

    // Queues a command as typed: checksum added when missing ("PNVGVER" → "$PNVGVER*4E").
    // Returns its id, or -1 with `error` set when it is not a sentence or is longer than the
    // dialect's receiver takes (lengthRefusal; nothing is sent then).
    int enqueue(const QString &typed, const CommandOptions &options = {}, QString *error = nullptr);
    // Cancels a queued or running command; false when it is not pending.
    bool cancel(int id);
    void cancelAll();

    bool isBusy() const { return current_.has_value(); }
    int pendingCount() const { return static_cast<int>(queue_.size()) + (isBusy() ? 1 : 0); }
    // The results of the last kHistoryLimit commands, oldest first: a tool left running for days
    // next to a receiver (a poll every second) keeps the recent ones, not every one.
    static constexpr qsizetype kHistoryLimit = 1000;
    const QList<CommandResult> &history() const { return history_; }

    // The reply rule for a command, among `rules` (a rule naming the first field wins).
    static const ReplyRule *findRule(std::span<const ReplyRule> rules, const Sentence &command);

signals:
    void commandSent(int id, const QString &sentence, int attempt);
    void replyReceived(int id, const QString &line);
    // The same reply as decoded by the link (the message is valid only during the signal).
    void replyDecoded(int id, const gnss::SentenceEvent &event);
    void commandFinished(const gnss::link::CommandResult &result);
    void baudChanged(int baud);
    void idle();

private:
    struct Pending {
        int id;
        std::string line; // the complete sentence
        CommandOptions options;
    };
    enum class Phase { Waiting, PreSwitch, SwitchingBaud, FallingBack };

    void startNext();
    void sendCurrent();
    void onEvent(const SentenceEvent &event);
    void onTimeout();
    void onLinkDown();
    void finish(CommandOutcome outcome, const QString &detail);
    void beginBaudSwitch(int delayMs);
    void switchTo(int baud);
    const ReplyRule *ruleFor(const Sentence &command) const;
    int baudFromCommand() const;

    QPointer<Transport> transport_;
    QPointer<SentenceStream> stream_;
    const Dialect *dialect_ = nullptr;
    std::vector<const Dialect *> others_;
    std::deque<Pending> queue_;
    std::optional<Pending> current_;
    Sentence command_; // views into current_->line
    const ReplyRule *rule_ = nullptr;
    ReplyProgress progress_;
    CommandResult result_;
    Phase phase_ = Phase::Waiting;
    int targetBaud_ = 0;
    QTimer timer_;
    QElapsedTimer elapsed_;
    QList<CommandResult> history_;
    // Keeps `r` in the history (the oldest dropped past kHistoryLimit) and says it is finished.
    void conclude(const CommandResult &r);
    int nextId_ = 1;
};

} // namespace gnss::link
