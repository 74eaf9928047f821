// Before any Qt header: core headers have members named emit, which Qt defines as a macro.

#include "config/utf8_text.h"
#include "core/dialect_registry.h"
#include "core/sentence_builder.h"
#include "core/settings_plan.h"
#include "core/stream_decoder.h"

#include "config/settings_engine.h"

#include "config/apply_plan.h"

#include "config/refusal_text.h"
#include "config/schema_texts.h"
#include "config/setting_values.h"
#include "link/connection.h"
#include "link/transport.h"

#include <QDateTime>

#include <algorithm>

namespace gnss::config {

QString verdictName(Verdict v) {
    switch (v) {
    case Verdict::Verified: return SettingsEngine::tr("verified");
    case Verdict::Echoed: return SettingsEngine::tr("confirmed by its reply (write-only)");
    case Verdict::Refused: return SettingsEngine::tr("refused before sending");
    case Verdict::NotTaken: return SettingsEngine::tr("not taken");
    case Verdict::NotReported: return SettingsEngine::tr("not reported");
    case Verdict::WrittenUnverified: return SettingsEngine::tr("sent (write-only, not verifiable)");
    case Verdict::NotSent: return SettingsEngine::tr("not applied (command failed)");
    case Verdict::NotReadBack:
        return SettingsEngine::tr("taken, not read back: the link was lost (read back when it "
                                  "returns)");
    case Verdict::Unconfirmed:
        return SettingsEngine::tr("unconfirmed: the link was lost before the answer (read back "
                                  "when it returns)");
    }
    return {};
}

int OperationReport::failedCommands() const {
    int n = 0;
    for (const auto &c : commands) n += succeeded(c) ? 0 : 1;
    return n;
}

int OperationReport::failedChecks() const {
    int n = 0;
    for (const auto &c : checks) n += isGood(c.verdict) ? 0 : 1;
    return n;
}

bool OperationReport::refusedBeforeSending() const {
    return commands.isEmpty() && !error.isEmpty() && !cancelled;
}

SettingsEngine::SettingsEngine(QObject *parent) : QObject(parent) {
    qRegisterMetaType<OperationReport>();
}

SettingsEngine::SettingsEngine(link::CommandQueue *queue, const Dialect *dialect, QObject *parent)
    : SettingsEngine(parent) {
    attach(queue, dialect);
}

SettingsEngine::~SettingsEngine() = default;

void SettingsEngine::attach(link::Connection *connection, const Dialect *dialect) {
    attach(connection ? connection->commands() : nullptr, dialect,
           connection ? connection->transport() : nullptr);
}

void SettingsEngine::attach(link::CommandQueue *queue, const Dialect *dialect,
                            link::Transport *transport) {
    if (isBusy() && queue != queue_) {
        report_.error = tr("the link changed during the operation");
        pending_.clear();
        end();
    }
    if (transport != transport_) {
        QObject::disconnect(transportConnection_);
        transportConnection_ = {};
        if (transport)
            transportConnection_ = connect(transport, &link::Transport::stateChanged, this,
                                           &SettingsEngine::onTransportState);
    }
    transport_ = transport;
    const bool newQueue = queue != queue_;
    if (newQueue) {
        QObject::disconnect(queueConnection_);
        queue_ = queue;
        QObject::disconnect(replyConnection_);
        replyValues_.clear();
        if (queue) {
            queueConnection_ = connect(queue, &link::CommandQueue::commandFinished, this,
                                       &SettingsEngine::onCommandFinished);
            replyConnection_ = connect(queue, &link::CommandQueue::replyDecoded, this,
                                       &SettingsEngine::onReplyDecoded);
        }
    }
    if (dialect != dialect_) {
        dialect_ = dialect;
        reported_.clear();
        written_.clear();
        interrupted_.clear();
        unread_.clear();
        readBackDue_ = false;
        identity_ = {};
        emit dialectChanged(dialect);
        emit valuesChanged();
    }
    if (newQueue) emit queueChanged();
    if (newQueue && queue) onTransportState(); // a new link to the same receiver: read back
}

bool SettingsEngine::canSend() const {
    return queue_ && (!transport_ || transport_->canWrite());
}

QString SettingsEngine::sendRefusal() const {
    if (!queue_ || !transport_ || transport_->canWrite()) return {};
    const QString why = transport_->readOnlyReason();
    return why.isEmpty() ? tr("%1 cannot take commands").arg(transport_->description()) : why;
}

void SettingsEngine::forget() {
    reported_.clear();
    written_.clear();
    interrupted_.clear();
    unread_.clear();
    emit valuesChanged();
}

std::vector<std::string> SettingsEngine::pendingReadBack() const {
    std::vector<std::string> keys;
    for (const auto &c : interrupted_) keys.push_back(c.key);
    return keys;
}

void SettingsEngine::onTransportState() {
    // The link is (back) up after an apply it dropped in (its transport open again, or a new
    // queue attached): its settings are read back as soon as nothing else runs.
    if ((interrupted_.empty() && unread_.empty()) || !queue_ ||
        (transport_ && !transport_->isOpen()))
        return;
    readBackDue_ = true;
    QMetaObject::invokeMethod(this, &SettingsEngine::readBackIfDue, Qt::QueuedConnection);
}

void SettingsEngine::readBackIfDue() {
    if (!readBackDue_ || isBusy() || (interrupted_.empty() && unread_.empty()) || !dialect_) return;
    if (!canSend() || (transport_ && !transport_->isOpen())) return; // at the next return
    readBackDue_ = false;
    if (interrupted_.empty()) { // a read the link dropped in: the same read again
        const std::vector<std::string> keys = std::move(unread_);
        unread_.clear();
        read(keys);
        return;
    }
    if (!begin(Operation::ReadBack, tr("Read back after the link returned"))) return;
    phase_ = Phase::Verify;
    std::vector<std::string> keys;
    for (const auto &c : interrupted_) {
        applying_.push_back({c.key, c.wanted});
        const SettingDef *def = findSetting(dialect_->settings, c.key);
        if (def && isReadable(*def)) keys.push_back(c.key);
    }
    const EncodeResult q = keys.empty() ? EncodeResult{} : encodeQueries(*dialect_, keys);
    if (!q.ok()) report_.error = tr("could not read back: %1").arg(refusalText(q, dialect_->id));
    if (!q.ok() || q.sentences.empty()) {
        finishReadBack();
        end();
        return;
    }
    for (const auto &k : keys) reported_.erase(k);
    if (!enqueue(q.sentences)) {
        const std::set<int> ids = pending_;
        for (int id : ids)
            if (queue_ && !queue_->cancel(id)) pending_.erase(id);
        if (pending_.empty() && isBusy()) {
            finishReadBack();
            end();
        }
    }
}

// ---- Values ---------------------------------------------------------------------------------

ValueState SettingsEngine::state(std::string_view key) const {
    if (reported_.find(key) != reported_.end()) return ValueState::Reported;
    if (written_.find(key) != written_.end()) return ValueState::Written;
    const SettingDef *def = dialect_ ? findSetting(dialect_->settings, key) : nullptr;
    if (def && def->access == SettingAccess::WriteOnly) return ValueState::WriteOnly;
    return ValueState::NotRead;
}

std::optional<std::string> SettingsEngine::receiverValue(std::string_view key) const {
    if (auto it = reported_.find(key); it != reported_.end()) return it->second;
    if (auto it = written_.find(key); it != written_.end()) return it->second;
    return std::nullopt;
}

QString SettingsEngine::displayValue(std::string_view key) const {
    switch (state(key)) {
    case ValueState::Reported: return qs(*receiverValue(key));
    case ValueState::Written:
        return tr("%1 (set here; write-only, not read back)").arg(qs(*receiverValue(key)));
    case ValueState::WriteOnly: return tr("unknown (write-only)");
    case ValueState::NotRead: break;
    }
    return QStringLiteral("\u2014");
}

std::vector<KeyValue> SettingsEngine::knownValues() const {
    std::vector<KeyValue> out;
    if (!dialect_) return out;
    for (const auto &def : dialect_->settings)
        if (auto v = receiverValue(def.key)) out.push_back({std::string(def.key), *v});
    return out;
}

std::vector<KeyValue> SettingsEngine::changesFrom(const std::vector<KeyValue> &values) const {
    std::vector<KeyValue> out;
    for (const auto &kv : values) {
        const SettingDef *def = dialect_ ? findSetting(dialect_->settings, kv.key) : nullptr;
        const auto rv = receiverValue(kv.key);
        if (def && rv && sameValue(*def, kv.value, *rv)) continue;
        out.push_back(kv);
    }
    return out;
}

// ---- Operations -----------------------------------------------------------------------------

bool SettingsEngine::begin(Operation op, const QString &title) {
    if (isBusy()) return false;
    report_ = {};
    report_.operation = op;
    report_.title = title;
    pending_.clear();
    done_ = total_ = 0;
    cancelled_ = false;
    action_.reset();
    applying_.clear();
    phase_ = Phase::Commands;
    if (!dialect_ || !queue_) {
        report_.error = !dialect_ ? tr("no receiver dialect known yet: connect to a receiver "
                                       "first")
                                  : tr("not connected to a receiver");
        emit finished(report_);
        return false;
    }
    op_ = op;
    emit busyChanged(true);
    return true;
}

bool SettingsEngine::enqueue(const std::vector<std::string> &sentences) {
    for (const auto &s : sentences) {
        QString error;
        const int id = queue_->enqueue(qs(s), optionsFor(s), &error);
        if (id < 0) {
            report_.error = error;
            return false;
        }
        pending_.insert(id);
        ++total_;
    }
    emit progress(done_, total_, report_.title);
    return true;
}

link::CommandOptions SettingsEngine::optionsFor(const std::string &sentence) const {
    link::CommandOptions o;
    if (!dialect_ || !transport_) return o;
    if (const auto to = lineBaudAfter(*dialect_, sentence, transport_->baud(), applying_))
        o.newBaud = *to;
    return o;
}

bool SettingsEngine::read(const std::vector<std::string> &keys) {
    if (!begin(Operation::Read, tr("Read settings"))) return false;
    std::vector<std::string> wanted;
    if (keys.empty()) {
        for (const auto &def : dialect_->settings)
            if (isReadable(def)) wanted.emplace_back(def.key);
    } else {
        for (const auto &k : keys) {
            const SettingDef *def = findSetting(dialect_->settings, k);
            if (!def) {
                report_.error = refusalText(unknownSetting(*dialect_, k), dialect_->id);
                end();
                return false;
            }
            // By its schema key, however it was typed ("ELGPS", "rtk.elgps").
            if (isReadable(*def)) wanted.emplace_back(def->key);
        }
    }
    std::vector<std::string> sentences;
    if (!wanted.empty()) {
        const EncodeResult q = encodeQueries(*dialect_, wanted);
        if (!q.ok()) {
            report_.error = refusalText(q, dialect_->id);
            end();
            return false;
        }
        sentences = q.sentences;
    }
    // The identity (model, firmware) for profiles and `get`, unless it is known or a query
    // already brings it.
    if ((keys.empty() || identity().model.empty()) && !dialect_->probeCommand.empty() &&
        std::find(sentences.begin(), sentences.end(), dialect_->probeCommand) == sentences.end())
        sentences.insert(sentences.begin(), std::string(dialect_->probeCommand));
    for (const auto &k : wanted) reported_.erase(k);
    reading_ = wanted;
    if (sentences.empty()) {
        end();
        return true;
    }
    if (!enqueue(sentences)) {
        cancel();
        if (pending_.empty()) end();
        return false;
    }
    return true;
}

bool SettingsEngine::apply(const std::vector<KeyValue> &typed) {
    if (!begin(Operation::Apply, tr("Apply settings"))) return false;
    // Each by its schema key, however it was typed ("PVTRATE", "rtk.pvtrate"): the read-back
    // that verifies it reports it so.
    std::vector<KeyValue> values;
    for (const auto &kv : typed) {
        const SettingDef *def = findSetting(dialect_->settings, kv.key);
        if (!def || !isWritable(*def)) {
            report_.error = def ? tr("%1 cannot be set").arg(qs(kv.key))
                                : refusalText(unknownSetting(*dialect_, kv.key), dialect_->id);
            end();
            return false;
        }
        values.push_back({std::string(def->key), kv.value});
    }
    const std::vector<KeyValue> changes = changesFrom(values);
    if (changes.empty()) {
        report_.nothingToDo = true;
        end();
        return true;
    }
    applying_ = withCompanions(
            *dialect_, changes, [this](std::string_view key) { return receiverValue(key); },
            &report_.companions);
    EncodeResult enc = encodeSettings(*dialect_, applying_);
    refuseLongSentences(enc, dialect_->maxSentenceLength);
    if (!enc.ok()) {
        report_.error = tr("nothing was sent: %1").arg(refusalText(enc, dialect_->id));
        for (const auto &kv : changes)
            report_.checks.push_back({kv.key, kv.value, {}, Verdict::Refused});
        end();
        return false;
    }
    // Write-only values are known again from this apply's echoes (PNVGRZA) or its outcome.
    for (const auto &kv : applying_)
        if (const SettingDef *def = findSetting(dialect_->settings, kv.key);
            def && !isReadable(*def))
            written_.erase(kv.key);
    // Restarts, then speed changes, then protocol changes last: after them the rest would
    // not arrive, or not be answered on the same terms.
    orderForSending(*dialect_, enc.sentences);
    if (!enqueue(enc.sentences)) {
        cancel();
        if (pending_.empty()) end();
        return false;
    }
    return true;
}

bool SettingsEngine::runAction(Action action) {
    const ActionDef *def = dialect_ ? findAction(*dialect_, action) : nullptr;
    const QString title = def ? SchemaTexts(dialect_->id)(def->label) : tr("Action");
    if (!begin(Operation::Action, title)) return false;
    if (!def) {
        report_.error = tr("the %1 receiver has no '%2' command")
                                .arg(qs(dialect_->displayName), qs(actionName(action)));
        end();
        return false;
    }
    action_ = action;
    if (!enqueue({actionSentence(*def)})) {
        end();
        return false;
    }
    return true;
}

std::vector<Action> SettingsEngine::availableActions() const {
    std::vector<Action> out;
    if (!dialect_) return out;
    for (const auto &a : dialect_->actions) out.push_back(a.action);
    return out;
}

void SettingsEngine::cancel() {
    if (!isBusy()) return;
    cancelled_ = true;
    report_.cancelled = true;
    const std::set<int> ids = pending_;
    for (int id : ids)
        if (queue_ && !queue_->cancel(id)) pending_.erase(id);
    if (pending_.empty() && isBusy()) phaseDone();
}

void SettingsEngine::onCommandFinished(const link::CommandResult &r) {
    if (!pending_.count(r.id)) return;
    pending_.erase(r.id);
    ++done_;
    report_.commands.append(r);
    absorb(r);
    emit commandFinished(r);
    emit progress(done_, total_, report_.title);
    if (pending_.empty()) phaseDone();
}

void SettingsEngine::onReplyDecoded(int id, const SentenceEvent &ev) {
    // The link decoded the reply once; the dialect reads its values and identity from that.
    if (!pending_.count(id) || !ev.message || !dialect_) return;
    std::vector<KeyValue> &out = replyValues_[id];
    if (dialect_->extractSettings) dialect_->extractSettings(*ev.message, out);
    if (dialect_->updateState) dialect_->updateState(*ev.message, identity_);
}

void SettingsEngine::absorb(const link::CommandResult &r) {
    const auto found = replyValues_.find(r.id);
    if (found == replyValues_.end()) return;
    const std::vector<KeyValue> out = std::move(found->second);
    replyValues_.erase(found);
    // A list reported one item per sentence (NVS PNVGIDL SHOW) is joined with ';'.
    std::set<std::string> seen;
    // The echo of a set (PNVGRTK, PNVGPPS) is no read-back of a readable setting being set: it
    // stays as it was until the read-back (which the link may not let happen).
    const bool setting = op_ == Operation::Apply && phase_ == Phase::Commands;
    auto beingSet = [&](std::string_view key) {
        return std::any_of(applying_.begin(), applying_.end(),
                           [&](const KeyValue &a) { return a.key == key; });
    };
    for (const auto &kv : out) {
        const SettingDef *def = findSetting(dialect_->settings, kv.key);
        if (!def) continue;
        if (setting && def->access != SettingAccess::WriteOnly && beingSet(kv.key)) continue;
        auto &target = def->access == SettingAccess::WriteOnly ? written_ : reported_;
        if (def->type == SettingType::List && seen.count(kv.key)) {
            std::string &v = target[kv.key];
            if (!kv.value.empty()) v += (v.empty() ? "" : ";") + kv.value;
        } else {
            target[kv.key] = kv.value;
        }
        seen.insert(kv.key);
    }
    if (!out.empty()) emit valuesChanged();
}

void SettingsEngine::phaseDone() {
    if (op_ == Operation::ReadBack) {
        finishReadBack();
        end();
        return;
    }
    if (op_ == Operation::Apply && phase_ == Phase::Commands && !cancelled_) {
        startVerify();
        return;
    }
    if (op_ == Operation::Apply) finishVerify();
    if (op_ == Operation::Read) finishRead();
    if (op_ == Operation::Action && action_ == Action::RestoreDefaults && !cancelled_ &&
        report_.failedCommands() == 0)
        forget(); // the receiver restarts with its defaults: read them again
    end();
}

void SettingsEngine::startVerify() {
    const bool linkLost = anyLinkLost(report_.commands);
    std::vector<std::string> keys;
    for (const auto &kv : applying_) {
        const SettingDef *def = findSetting(dialect_->settings, kv.key);
        if (def && isReadable(*def)) keys.push_back(kv.key);
    }
    if (linkLost || keys.empty() || !queue_) {
        finishVerify();
        end();
        return;
    }
    phase_ = Phase::Verify;
    const EncodeResult q = encodeQueries(*dialect_, keys);
    for (const auto &k : keys) reported_.erase(k);
    if (!q.ok() || q.sentences.empty() || !enqueue(q.sentences)) {
        if (!q.ok())
            report_.error = tr("could not read back: %1").arg(refusalText(q, dialect_->id));
        if (pending_.empty()) {
            finishVerify();
            end();
        }
    }
}

std::optional<std::string> SettingsEngine::reportedInApply(const SettingDef &def) const {
    // Readable: what the receiver reported. Write-only: its echo in this apply (PNVGRZA answers
    // with the values in force; the apply forgot the values written before).
    const auto &known = isReadable(def) ? reported_ : written_;
    const auto it = known.find(def.key);
    return it == known.end() ? std::nullopt : std::optional<std::string>(it->second);
}

void SettingsEngine::finishVerify() {
    if (!report_.checks.empty()) return;
    const bool linkLost = anyLinkLost(report_.commands);
    // Without the link lost, a setting's command failed when any of the apply's did (the
    // read-back's come after them); with it, each command's own outcome says.
    std::map<std::string, CommandFate, std::less<>> fates;
    if (linkLost) {
        std::vector<PlannedCommand> plan;
        if (planWrites(*dialect_, applying_, plan).empty())
            for (const PlannedCommand &p : plan) {
                const CommandFate f =
                        fateOf(p.command->write(p.values).sentences, report_.commands);
                for (const auto &kv : p.values) fates[kv.key] = f;
            }
    }
    const CommandFate allFate =
            std::all_of(report_.commands.begin(), report_.commands.end(), succeeded)
                    ? CommandFate::Taken
                    : CommandFate::NotSent;
    bool readableLost = false;
    for (const auto &kv : applying_) {
        const SettingDef *def = findSetting(dialect_->settings, kv.key);
        if (!def) continue;
        SettingFacts facts;
        facts.reported = reportedInApply(*def);
        facts.linkLost = linkLost;
        facts.readBackRan = phase_ == Phase::Verify;
        if (linkLost) {
            const auto found = fates.find(kv.key);
            facts.fate = found == fates.end() ? CommandFate::Unconfirmed : found->second;
        } else {
            facts.fate = allFate;
        }
        const SettingCheck c = judge(*def, kv.value, facts);
        if (isReadable(*def)) {
            readableLost = readableLost || linkLost;
            // What the receiver has now is not known until the read-back.
            const bool readBack = facts.reported && facts.readBackRan;
            if (linkLost && !readBack && facts.fate != CommandFate::NotSent)
                reported_.erase(kv.key);
        } else if (c.verdict == Verdict::WrittenUnverified) {
            written_[kv.key] = kv.value;
        } else if (c.verdict == Verdict::NotSent) {
            written_.erase(kv.key);
        }
        report_.checks.push_back(c);
    }
    if (readableLost) {
        // An earlier apply still waiting for its read-back keeps its other settings.
        std::vector<SettingCheck> earlier = std::move(interrupted_);
        interrupted_ = report_.checks;
        for (auto &e : earlier)
            if (std::none_of(interrupted_.begin(), interrupted_.end(),
                             [&](const SettingCheck &c) { return c.key == e.key; }))
                interrupted_.push_back(std::move(e));
        report_.readBackOnReturn = true;
        readBackDue_ = false; // the link is to come back first
    }
    emit valuesChanged();
}

void SettingsEngine::finishRead() {
    // Dropped in by the link (not cancelled): the same settings are read again on its return.
    if (anyLinkLost(report_.commands) && !cancelled_ && !reading_.empty()) {
        unread_ = reading_;
        report_.readBackOnReturn = true;
        readBackDue_ = false; // the link is to come back first
    } else {
        unread_.clear();
    }
    reading_.clear();
}

void SettingsEngine::finishReadBack() {
    const bool linkLost = anyLinkLost(report_.commands);
    for (const SettingCheck &c : interrupted_) {
        const SettingDef *def = findSetting(dialect_->settings, c.key);
        if (!def) {
            report_.checks.push_back(c);
            continue;
        }
        const auto it = reported_.find(c.key);
        report_.checks.push_back(judgeReadBack(
                *def, c, it == reported_.end() ? std::nullopt : std::optional(it->second),
                linkLost));
    }
    // Lost again: read back at the next return. Done, or cancelled by the user: no more.
    if (linkLost && !cancelled_)
        report_.readBackOnReturn = true;
    else
        interrupted_.clear();
    emit valuesChanged();
}

void SettingsEngine::end() {
    if (op_ == Operation::None) {
        emit finished(report_);
        return;
    }
    op_ = Operation::None;
    pending_.clear();
    emit busyChanged(false);
    emit finished(report_);
    // The link came back while something else ran.
    if (readBackDue_)
        QMetaObject::invokeMethod(this, &SettingsEngine::readBackIfDue, Qt::QueuedConnection);
}

// ---- Profiles -------------------------------------------------------------------------------

Profile SettingsEngine::exportProfile() const {
    Profile p;
    if (!dialect_) return p;
    p.dialect = std::string(dialect_->id);
    p.model = identity().model;
    p.firmware = identity().firmware;
    p.created = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
    for (const auto &def : dialect_->settings) {
        if (!isWritable(def)) continue;
        if (auto v = receiverValue(def.key)) {
            p.values.push_back({std::string(def.key), *v});
            if (state(def.key) == ValueState::Written) p.writeOnly.emplace_back(def.key);
        }
    }
    return p;
}

std::vector<DiffEntry> SettingsEngine::diff(const Profile &p) const {
    std::vector<DiffEntry> out;
    for (const auto &kv : p.values) {
        const SettingDef *def = dialect_ ? findSetting(dialect_->settings, kv.key) : nullptr;
        if (!def || !isWritable(*def)) continue;
        const auto rv = receiverValue(kv.key);
        if (rv && sameValue(*def, kv.value, *rv)) continue;
        out.push_back({kv.key, kv.value, rv.value_or(std::string()), rv.has_value()});
    }
    return out;
}

bool SettingsEngine::applyProfile(const Profile &p) {
    if (const QString why = profileMismatch(p, dialect_, identity().model); !why.isEmpty()) {
        if (!begin(Operation::Apply, tr("Apply profile"))) return false;
        report_.error = why;
        end();
        return false;
    }
    return apply(p.values);
}

} // namespace gnss::config
