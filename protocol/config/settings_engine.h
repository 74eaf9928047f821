#pragma once
// SettingsEngine: a receiver's settings through the command queue, for the settings dock and
// `gnss-cli config`. Knows no vendor: everything comes from the dialect record (schema with each
// row's command and role, encodeSettings/encodeQueries/extractSettings, reply rules, actions,
// the host port's speed command); it plans from those, never from help or error texts.
//
//   read   every readable setting (or the keys given): encodeQueries → queue → replies →
//          extractSettings. Write-only settings stay "unknown (write-only)" until this program
//          sets them.
//   apply  only what differs from the receiver; settings the dialect writes with one command
//          (the schema rows' `command`: PNVGRZA's baud and protocol) go together; commands sorted
//          so that restarts, speed and protocol changes come last; every command's outcome
//          reported; then the changed readable settings are read back and each is marked
//          verified, not taken, or not reported.
//          The link lost in the middle (a cable pulled): every command still has its outcome
//          (answered, sent with its answer lost, not sent); a setting is verified only by a
//          read-back, so those whose commands went out are "not read back" or "unconfirmed",
//          their old values forgotten; when the link is back the engine reads the apply's
//          settings back by itself (Operation::ReadBack) and reports each against the value
//          wanted.
//   action save to flash / restore defaults / cold, warm, hot start, where the dialect has one.
//
// One operation at a time, with progress; cancel() stops it (queued commands are cancelled).
#include "config/apply_verdicts.h"
#include "config/dialect_actions.h"
#include "config/settings_profile.h"

#include "core/dialect.h"
#include "core/stream_decoder.h"
#include "link/command_queue.h"
#include "state/receiver_state.h"

#include <QObject>
#include <QPointer>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gnss::link {
class Connection;
class Transport;
} // namespace gnss::link

namespace gnss::config {

enum class Operation { None, Read, Apply, Action, ReadBack };

QString verdictName(Verdict v);

struct OperationReport {
    Operation operation = Operation::None;
    QString title;                       // "Read", "Apply", "Save to flash"
    QList<link::CommandResult> commands; // every command's outcome, in order
    std::vector<SettingCheck> checks;    // apply: one per setting changed
    std::vector<KeyValue> companions;    // apply: settings sent along (same command)
    QString error;                       // why nothing (more) was sent
    bool cancelled = false;
    bool nothingToDo = false; // apply: every value was already in force
    // apply or read: the link went in the middle; its settings are read (back) when the link
    // returns.
    bool readBackOnReturn = false;

    // Commands that were neither accepted nor sent.
    int failedCommands() const;
    // Checks that are not good (config::isGood).
    int failedChecks() const;
    // Refused before anything was sent: a value its command cannot carry, a setting that cannot
    // be set (a wrong request, where a failed command is the receiver's doing).
    bool refusedBeforeSending() const;
    bool ok() const {
        return error.isEmpty() && !cancelled && !failedCommands() && !failedChecks();
    }
};

enum class ValueState {
    NotRead,   // readable, not read yet (or not reported)
    Reported,  // as the receiver reported it
    WriteOnly, // the receiver cannot report it, and it was not set here
    Written,   // write-only, set by this program (not read back)
};

class SettingsEngine : public QObject {
    Q_OBJECT
public:
    explicit SettingsEngine(QObject *parent = nullptr);
    SettingsEngine(link::CommandQueue *queue, const Dialect *dialect, QObject *parent = nullptr);
    ~SettingsEngine() override;

    // The queue commands go through and the receiver's dialect; a new dialect forgets every
    // value (a new queue alone keeps them: the same receiver after a reconnect).
    // `transport` (optional) lets a speed change of another port than the host's go through
    // without the link following it.
    void attach(link::CommandQueue *queue, const Dialect *dialect,
                link::Transport *transport = nullptr);
    void attach(link::Connection *connection, const Dialect *dialect);
    const Dialect *dialect() const { return dialect_; }
    link::CommandQueue *queue() const { return queue_; }
    bool isBusy() const { return op_ != Operation::None; }
    // Whether commands can go to the receiver (a replayed log cannot take any, nor can a receiver
    // that gpsd holds).
    bool canSend() const;
    // Why they cannot, in words for the user ("gpsd owns the port: ..."), when a link is attached
    // that takes no commands; empty otherwise.
    QString sendRefusal() const;
    // Forgets what was read and written (the receiver restarted with other settings).
    void forget();
    // The settings of an apply the link dropped in, to read back when it returns (empty: none).
    std::vector<std::string> pendingReadBack() const;

    // ---- Values -------------------------------------------------------------------------
    ValueState state(std::string_view key) const;
    // The receiver's value as reported, or as written when write-only; nullopt when unknown.
    std::optional<std::string> receiverValue(std::string_view key) const;
    // For display: the value, "unknown (write-only)", "— (not read)".
    QString displayValue(std::string_view key) const;
    // Every known value (reported or written), schema order.
    std::vector<KeyValue> knownValues() const;
    const ReceiverIdentity &identity() const { return identity_.identity; }
    // `values` reduced to what differs from the receiver (unknown counts as different).
    std::vector<KeyValue> changesFrom(const std::vector<KeyValue> &values) const;

    // ---- Operations (asynchronous; finished() at the end). False when one cannot start:
    // busy, no queue or dialect, or (apply) a value refused before anything was sent — then
    // finished() still reports why. ---------------------------------------------------------
    bool read(const std::vector<std::string> &keys = {});
    bool apply(const std::vector<KeyValue> &values);
    bool runAction(Action action);
    void cancel();
    std::vector<Action> availableActions() const;

    // ---- Profiles -----------------------------------------------------------------------
    Profile exportProfile() const;
    // Profile entries that differ from the receiver (unknown receiver values included).
    std::vector<DiffEntry> diff(const Profile &p) const;
    bool applyProfile(const Profile &p);

    // The last report (valid after finished()).
    const OperationReport &lastReport() const { return report_; }

signals:
    void dialectChanged(const gnss::Dialect *dialect);
    void queueChanged(); // another link (connected, reconnected, or gone)
    void busyChanged(bool busy);
    void progress(int done, int total, const QString &step);
    void commandFinished(const gnss::link::CommandResult &result);
    void valuesChanged();
    void finished(const gnss::config::OperationReport &report);

private:
    enum class Phase { Commands, Verify };
    bool begin(Operation op, const QString &title);
    bool enqueue(const std::vector<std::string> &sentences);
    void onCommandFinished(const link::CommandResult &r);
    void onReplyDecoded(int id, const SentenceEvent &ev);
    void absorb(const link::CommandResult &r);
    void phaseDone();
    void startVerify();
    // The apply's checks, by the verdict rule (apply_verdicts.h), with or without the link lost.
    void finishVerify();
    std::optional<std::string> reportedInApply(const SettingDef &def) const;
    void end();
    void finishRead();
    void finishReadBack();
    void onTransportState();
    void readBackIfDue();
    link::CommandOptions optionsFor(const std::string &sentence) const;

    QPointer<link::CommandQueue> queue_;
    QPointer<link::Transport> transport_;
    QMetaObject::Connection queueConnection_, replyConnection_, transportConnection_;
    const Dialect *dialect_ = nullptr;
    std::map<int, std::vector<KeyValue>> replyValues_; // per command, from its decoded replies
    std::map<std::string, std::string, std::less<>> reported_, written_;
    ReceiverState identity_;

    Operation op_ = Operation::None;
    Phase phase_ = Phase::Commands;
    std::set<int> pending_;
    int done_ = 0, total_ = 0;
    bool cancelled_ = false;
    std::optional<Action> action_;
    std::vector<KeyValue> applying_; // changes + companions
    // The checks of the apply the link dropped in, until its read-back after the return.
    std::vector<SettingCheck> interrupted_;
    bool readBackDue_ = false; // the link came back since: read them when idle
    // A read the link dropped in: what it asked for (reading_), read again when the link returns
    // (unread_), so the form does not keep showing half of what the receiver has.
    std::vector<std::string> reading_, unread_;
    OperationReport report_;
};

} // namespace gnss::config

Q_DECLARE_METATYPE(gnss::config::OperationReport)
