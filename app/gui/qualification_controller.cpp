// The Qualification dock's controller: campaigns on the window's receivers, their runs, the
// positions for the accuracy, and the report.
#include "gui/qualification_controller.h"

#include "config/settings_engine.h"
#include "config/settings_snapshot.h"
#include "link/connection.h"
#include "models/receiver_session.h"
#include "qualify/accuracy_panel.h"
#include "qualify/ttff_campaign.h"
#include "session/receiver_link.h"

namespace gnss::app {

namespace {

QString portOf(const link::SourceSpec &spec) {
    using Kind = link::SourceSpec::Kind;
    return spec.kind == Kind::Serial || spec.kind == Kind::Tcp ? spec.place() : spec.displayName();
}

} // namespace

QualificationController::QualificationController(Receivers receivers, QObject *parent)
    : QObject(parent), receivers_(std::move(receivers)) {
    tick_.setInterval(1000);
    connect(&tick_, &QTimer::timeout, this, [this] {
        if (running()) refresh();
        refreshAccuracy();
    });
    tick_.start();
}

void QualificationController::attach(ui::QualificationView *view) {
    view_ = view;
    view->setDisplayPrefs(prefs_);
    connect(view, &ui::QualificationView::startRequested, this,
            [this](const ui::QualificationRequest &r) { start(r); });
    connect(view, &ui::QualificationView::cancelRequested, this, &QualificationController::cancel);
    connect(view->accuracy(), &ui::AccuracyPanel::referenceChanged, this,
            &QualificationController::refreshAccuracy);
    view->setRunning(running());
    view->setReceiverCount(int(receivers_.all().size()));
    refresh();
    refreshAccuracy();
}

void QualificationController::setDisplayPrefs(const ui::DisplayPrefs &prefs) {
    prefs_ = prefs;
    if (view_) view_->setDisplayPrefs(prefs);
    refreshAccuracy();
}

void QualificationController::follow(ui::ReceiverSession *s) {
    // A new connection (the state cleared) is another period: its positions start again.
    connect(s->state(), &ui::ReceiverStateModel::updated, this, [this, s] {
        if (s->state()->epochCount() == 0)
            positions_[s].clear();
        else
            positions_[s].add(s->state()->state().epoch);
    });
    connect(s, &QObject::destroyed, this, [this, s] { positions_.remove(s); });
    if (view_) view_->setReceiverCount(int(receivers_.all().size()));
}

bool QualificationController::running() const {
    for (const Entry &e : entries_)
        if (!e.done) return true;
    return false;
}

qualify::ReportReceiver QualificationController::identityOf(ui::ReceiverSession *s) const {
    qualify::ReportReceiver r;
    r.name = s->name();
    const ReceiverIdentity &id = s->state()->state().identity;
    r.model = QString::fromStdString(id.model);
    r.firmware = QString::fromStdString(id.firmware);
    r.port = portOf(s->link()->source());
    if (const link::Connection *c = s->link()->connection())
        r.baud = c->transport() ? c->transport()->baud() : 0;
    return r;
}

bool QualificationController::start(const ui::QualificationRequest &r) {
    if (running()) return false;
    QList<ui::ReceiverSession *> chosen;
    if (r.allReceivers)
        chosen = receivers_.all();
    else if (ui::ReceiverSession *s = receivers_.selected())
        chosen << s;
    QStringList refusals;
    for (ui::ReceiverSession *s : chosen) {
        link::Connection *conn = s->link()->connection();
        if (!conn || !conn->transport() || !conn->transport()->isOpen()) {
            refusals << tr("%1: not connected").arg(s->name());
            continue;
        }
        if (const QString no = s->link()->settings()->sendRefusal(); !no.isEmpty()) {
            refusals << tr("%1: %2").arg(s->name(), no);
            continue;
        }
        if (const QString no = qualify::TtffCampaign::refusal(s->dialect(), r.plan.starts);
            !no.isEmpty())
            refusals << tr("%1: %2").arg(s->name(), no);
    }
    if (chosen.isEmpty()) refusals << tr("No receiver to qualify.");
    if (!refusals.isEmpty()) {
        if (view_)
            view_->showMessage(refusals.join(QLatin1Char('\n')) + QLatin1Char('\n') +
                               tr("Nothing was sent."));
        return false;
    }
    request_ = r;
    entries_.clear();
    entries_.reserve(std::size_t(chosen.size()));
    started_ = QDateTime::currentDateTimeUtc();
    ended_ = {};
    clock_.start();
    for (ui::ReceiverSession *s : chosen) {
        link::Connection *conn = s->link()->connection();
        // Its settings as they are, for the report (read while it settles on a fix).
        if (config::SettingsEngine *engine = s->link()->settings(); !engine->isBusy())
            engine->read();
        Entry e;
        e.session = s;
        e.data = identityOf(s);
        // A child of its link: a receiver closed mid-campaign takes its campaign with it.
        e.campaign = new qualify::TtffCampaign(conn, s->dialect(), r.plan, conn);
        e.total = e.campaign->totalRuns();
        entries_.push_back(e);
    }
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        qualify::TtffCampaign *c = entries_[i].campaign;
        // Several receivers: each restart written to all at the same moment.
        c->setBarrier(entries_.size() > 1);
        connect(c, &qualify::TtffCampaign::readyToRestart, this, &QualificationController::go);
        connect(c, &qualify::TtffCampaign::progress, this, &QualificationController::go);
        connect(c, &qualify::TtffCampaign::runFinished, this,
                [this, i](const qualify::TtffRun &run) {
                    entries_[i].data.runs.push_back(run);
                    refresh();
                });
        auto end = [this, i] {
            if (i >= entries_.size() || entries_[i].done) return;
            entries_[i].done = true;
            finishedOne();
        };
        connect(c, &qualify::TtffCampaign::finished, this, end);
        connect(c, &QObject::destroyed, this, end);
    }
    if (view_) view_->setRunning(true);
    emit runningChanged(true);
    for (Entry &e : entries_) e.campaign->start();
    refresh();
    return true;
}

void QualificationController::go() {
    // Once every receiver still running waits to restart (one whose link is gone is not waited
    // for), all restart together.
    bool anyReady = false;
    for (const Entry &e : entries_) {
        if (!e.campaign || e.done || e.campaign->waitingForLink()) continue;
        if (!e.campaign->readyToGo()) return;
        anyReady = true;
    }
    if (!anyReady) return;
    for (Entry &e : entries_)
        if (e.campaign && !e.done) e.campaign->go();
}

void QualificationController::cancel() {
    for (Entry &e : entries_)
        if (e.campaign && !e.done) e.campaign->cancel();
}

void QualificationController::finishedOne() {
    if (running()) return;
    ended_ = QDateTime::currentDateTimeUtc();
    if (view_) view_->setRunning(false);
    refresh();
    emit runningChanged(false);
    emit message(tr("The qualification campaign has ended."));
}

void QualificationController::refresh() {
    if (!view_) return;
    QStringList lines;
    int done = 0, total = 0;
    std::vector<qualify::ReportReceiver> data;
    for (const Entry &e : entries_) {
        done += int(e.data.runs.size());
        total += e.total;
        const QString who = e.session ? e.session->name() : e.data.name;
        if (e.campaign && !e.done)
            lines << tr("%1: %2").arg(who, e.campaign->stateText());
        else
            lines << tr("%1: done, %n run(s)", nullptr, int(e.data.runs.size())).arg(who);
        data.push_back(e.data);
    }
    double left = -1;
    if (running() && done > 0) left = clock_.elapsed() / 1000.0 / done * (total - done);
    if (!entries_.empty()) view_->setProgress(lines, done, total, left);
    view_->setResults(data, request_.limits);
}

void QualificationController::refreshAccuracy() {
    if (!view_ || !view_->isVisible()) return;
    ui::ReceiverSession *s = receivers_.selected();
    static const compare::PositionSet none;
    view_->accuracy()->show(s && positions_.contains(s) ? positions_[s] : none);
}

qualify::ReportInput QualificationController::reportInput() const {
    qualify::ReportInput in;
    in.started = started_;
    in.ended = ended_.isValid() ? ended_ : QDateTime::currentDateTimeUtc();
    if (view_) in.reference = view_->accuracy()->reference();
    in.starts = request_.plan.starts;
    in.runsPerStart = request_.plan.runs;
    in.timeoutS = request_.plan.timeoutMs / 1000.0;
    in.pauseS = request_.plan.pauseMs / 1000.0;
    in.limits = request_.limits;
    in.length.symbol = ui::fmt::lengthUnit(prefs_.units);
    in.length.perMetre = ui::fmt::lengthFactor(prefs_.units);
    for (const Entry &e : entries_) {
        qualify::ReportReceiver r = e.data;
        if (e.session) {
            r.settings = config::settingsSnapshot(*e.session->link()->settings());
            const auto it = positions_.constFind(e.session.data());
            if (it != positions_.constEnd() && it->size()) {
                const auto point = in.reference ? in.reference : it->mean();
                if (point) {
                    const compare::Accuracy a = it->against(*point);
                    r.accuracy = a.report();
                    r.horizontalErrors = a.horizontalErrors();
                    r.verticalErrors = a.verticalErrors();
                }
                if (in.location.isEmpty())
                    if (const auto m = it->mean())
                        in.location = ui::fmt::latitude(m->latDeg, prefs_.coordinates) +
                                      QStringLiteral(", ") +
                                      ui::fmt::longitude(m->lonDeg, prefs_.coordinates);
            }
        }
        in.receivers.push_back(std::move(r));
    }
    return in;
}

QStringList QualificationController::writeReport(const QString &path, QString *error) const {
    return qualify::writeReport(reportInput(), path, error);
}

} // namespace gnss::app
