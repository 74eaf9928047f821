#include "base/base_station_view.h"

#include "base/base_plan.h"
#include "base/base_status.h"
#include "base/position_text.h"
#include "config/schema_texts.h"
#include "config/settings_engine.h"
#include "models/receiver_state_model.h"
#include "qualify/qualify_plots.h"
#include "sites/site_store.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <cmath>

namespace gnss::ui {

namespace {

QString roleText(OptionMeaning m) {
    switch (m) {
    case OptionMeaning::BaseFixed: return BaseStationView::tr("base at a set position");
    case OptionMeaning::BaseAveraging:
        return BaseStationView::tr("base averaging its own position");
    case OptionMeaning::Rover: return BaseStationView::tr("RTK rover");
    case OptionMeaning::Autonomous: return BaseStationView::tr("autonomous");
    default: return BaseStationView::tr("not read yet");
    }
}

QString ecefText(const wgs84::Ecef &p) {
    return QStringLiteral("%1, %2, %3").arg(p.x, 0, 'f', 3).arg(p.y, 0, 'f', 3).arg(p.z, 0, 'f', 3);
}

} // namespace

BaseStationView::BaseStationView(config::SettingsEngine *engine, ReceiverStateModel *state,
                                 QWidget *parent)
    : QWidget(parent), engine_(engine), state_(state) {
    setObjectName("baseStationView");
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    unsupported_ = new QLabel(this);
    unsupported_->setObjectName("baseUnsupported");
    unsupported_->setWordWrap(true);
    unsupported_->setContentsMargins(8, 8, 8, 8);
    outer->addWidget(unsupported_);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    outer->addWidget(scroll, 1);
    body_ = new QWidget(scroll);
    scroll->setWidget(body_);
    auto *layout = new QVBoxLayout(body_);

    // The base as the receiver has it.
    auto *statusRow = new QHBoxLayout;
    status_ = new QLabel(body_);
    status_->setObjectName("baseStatus");
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    statusRow->addWidget(status_, 1);
    auto *read = new QPushButton(tr("Read"), body_);
    read->setObjectName("baseRead");
    read->setToolTip(tr("Read the base settings from the receiver"));
    statusRow->addWidget(read, 0, Qt::AlignTop);
    layout->addLayout(statusRow);
    warning_ = new QLabel(body_);
    warning_->setObjectName("baseWarning");
    warning_->setWordWrap(true);
    warning_->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold"));
    warning_->hide();
    layout->addWidget(warning_);

    // Where the base is.
    auto *where = new QGroupBox(tr("Position of the base"), body_);
    auto *whereLayout = new QVBoxLayout(where);
    source_ = new QComboBox(where);
    source_->setObjectName("baseSource");
    source_->addItem(tr("Survey-in by the workbench"));
    source_->addItem(tr("Survey-in by the receiver"));
    source_->addItem(tr("Known position"));
    whereLayout->addWidget(source_);
    sourcePages_ = new QStackedWidget(where);
    whereLayout->addWidget(sourcePages_);

    auto *surveyPage = new QWidget(sourcePages_);
    auto *surveyLayout = new QVBoxLayout(surveyPage);
    surveyLayout->setContentsMargins(0, 0, 0, 0);
    auto *goalRow = new QHBoxLayout;
    goal_ = new QComboBox(surveyPage);
    goal_->setObjectName("surveyGoal");
    goal_->addItem(tr("For minutes"));
    goal_->addItem(tr("Until accuracy, m"));
    goalValue_ = new QDoubleSpinBox(surveyPage);
    goalValue_->setObjectName("surveyGoalValue");
    goalValue_->setDecimals(2);
    goalValue_->setRange(0.01, 1440);
    goalValue_->setValue(5);
    surveyButton_ = new QPushButton(tr("Start survey"), surveyPage);
    surveyButton_->setObjectName("surveyStart");
    goalRow->addWidget(goal_);
    goalRow->addWidget(goalValue_);
    goalRow->addWidget(surveyButton_);
    surveyLayout->addLayout(goalRow);
    progress_ = new QProgressBar(surveyPage);
    progress_->setObjectName("surveyProgress");
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    surveyLayout->addWidget(progress_);
    surveyText_ = new QLabel(surveyPage);
    surveyText_->setObjectName("surveyText");
    surveyText_->setWordWrap(true);
    surveyText_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    surveyLayout->addWidget(surveyText_);
    convergence_ = new ErrorSeriesPlot(surveyPage);
    convergence_->setObjectName("surveyConvergence");
    convergence_->setToolTip(tr("How far the running mean was from the mean now: horizontally and "
                                "vertically, a point a second"));
    convergence_->setMinimumHeight(110);
    surveyLayout->addWidget(convergence_, 1);
    sourcePages_->addWidget(surveyPage);

    auto *receiverPage = new QWidget(sourcePages_);
    auto *receiverLayout = new QFormLayout(receiverPage);
    receiverLayout->setContentsMargins(0, 0, 0, 0);
    receiverMinutes_ = new QSpinBox(receiverPage);
    receiverMinutes_->setObjectName("receiverSurveyMinutes");
    receiverMinutes_->setRange(1, 1440);
    receiverMinutes_->setValue(30);
    receiverMinutes_->setSuffix(tr(" min"));
    receiverLayout->addRow(tr("Averaging time:"), receiverMinutes_);
    receiverButton_ = new QPushButton(tr("Start the receiver's survey"), receiverPage);
    receiverButton_->setObjectName("receiverSurveyStart");
    receiverButton_->setToolTip(tr("Makes the receiver a base that averages its own position, "
                                   "with the station, interval and port below"));
    receiverLayout->addRow(receiverButton_);
    receiverText_ = new QLabel(receiverPage);
    receiverText_->setObjectName("receiverSurveyText");
    receiverText_->setWordWrap(true);
    receiverLayout->addRow(receiverText_);
    sourcePages_->addWidget(receiverPage);

    auto *knownPage = new QWidget(sourcePages_);
    auto *knownLayout = new QFormLayout(knownPage);
    knownLayout->setContentsMargins(0, 0, 0, 0);
    format_ = new QComboBox(knownPage);
    format_->setObjectName("knownFormat");
    format_->addItem(tr("Latitude, longitude, height"));
    format_->addItem(tr("ECEF X, Y, Z (m)"));
    knownLayout->addRow(tr("Typed as:"), format_);
    auto *positionRow = new QHBoxLayout;
    position_ = new QLineEdit(knownPage);
    position_->setObjectName("knownPosition");
    position_->setPlaceholderText(tr("55°45'04.3\"N, 37 37.104E, 166.6"));
    position_->setToolTip(tr("Degrees as decimals, degrees and minutes or DMS, with N/S/E/W or a "
                             "sign; the height in metres"));
    sitesButton_ = new QPushButton(tr("Sites"), knownPage);
    sitesButton_->setObjectName("baseSites");
    sitesButton_->setMenu(new QMenu(sitesButton_));
    positionRow->addWidget(position_, 1);
    positionRow->addWidget(sitesButton_);
    knownLayout->addRow(tr("Position:"), positionRow);
    msl_ = new QCheckBox(tr("Height above sea level (the receiver's geoid separation is added)"),
                         knownPage);
    msl_->setObjectName("knownMsl");
    knownLayout->addRow(msl_);
    sourcePages_->addWidget(knownPage);
    layout->addWidget(where);

    // What the base sends.
    auto *send = new QGroupBox(tr("Base settings"), body_);
    auto *form = new QFormLayout(send);
    antenna_ = new QDoubleSpinBox(send);
    antenna_->setObjectName("baseAntennaHeight");
    antenna_->setRange(0, 100);
    antenna_->setDecimals(3);
    antenna_->setSuffix(tr(" m"));
    antenna_->setToolTip(tr("From the mark up to the antenna reference point (a known position)"));
    form->addRow(tr("Antenna height:"), antenna_);
    station_ = new QSpinBox(send);
    station_->setObjectName("baseStation");
    form->addRow(tr("Station id:"), station_);
    interval_ = new QComboBox(send);
    interval_->setObjectName("baseInterval");
    form->addRow(tr("Observables:"), interval_);
    port_ = new QComboBox(send);
    port_->setObjectName("basePort");
    form->addRow(tr("RTCM on:"), port_);
    saveFlash_ = new QCheckBox(tr("Save to the receiver's flash once verified"), send);
    saveFlash_->setObjectName("baseSaveFlash");
    form->addRow(saveFlash_);
    auto *buttons = new QHBoxLayout;
    setButton_ = new QPushButton(tr("Set base"), send);
    setButton_->setObjectName("baseSet");
    auto *saveSite = new QPushButton(tr("Save as site…"), send);
    saveSite->setObjectName("baseSaveSite");
    saveSite->setToolTip(tr("Keep the survey's result (or the position typed) in the site list"));
    buttons->addWidget(setButton_);
    buttons->addWidget(saveSite);
    buttons->addStretch(1);
    form->addRow(buttons);
    verdicts_ = new QListWidget(send);
    verdicts_->setObjectName("baseVerdicts");
    verdicts_->setMinimumHeight(60);
    // A verdict is a sentence (twice as long in Russian): wrapped at the list's width.
    verdicts_->setWordWrap(true);
    verdicts_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    verdicts_->setResizeMode(QListView::Adjust);
    form->addRow(verdicts_);
    layout->addWidget(send);
    layout->addStretch(1);

    connect(read, &QPushButton::clicked, this, &BaseStationView::readBase);
    // The group is as tall as the page shown (a known position is one line, not the survey's
    // plot), so that Set base stays in sight on a laptop screen.
    auto fitPage = [pages = sourcePages_](int index) {
        pages->setCurrentIndex(index);
        for (int i = 0; i < pages->count(); ++i) {
            const auto height = i == index ? QSizePolicy::Preferred : QSizePolicy::Ignored;
            pages->widget(i)->setSizePolicy(QSizePolicy::Preferred, height);
        }
        pages->updateGeometry();
    };
    fitPage(0);
    connect(source_, &QComboBox::currentIndexChanged, sourcePages_, fitPage);
    connect(surveyButton_, &QPushButton::clicked, this,
            [this] { surveying_ ? stopSurvey() : startSurvey(); });
    connect(goal_, &QComboBox::currentIndexChanged, this,
            [this](int i) { goalValue_->setValue(i == 0 ? 5 : 0.5); });
    connect(receiverButton_, &QPushButton::clicked, this, [this] {
        base::BaseRequest q;
        q.kind = base::BaseRequest::Kind::Averaging;
        q.averagingMinutes = receiverMinutes_->value();
        const base::BasePlan plan = planWithForm(q);
        verdicts_->clear();
        if (!plan.ok()) return verdicts_->addItem(QString::fromStdString(plan.error));
        positionBefore_ = engine_->receiverValue(roles_->position->key);
        survey_ = base::SurveyIn(base::SurveyGoal{});
        if (!engine_->apply(plan.values)) return;
        pending_ = Pending::Apply;
        receiverSurveyStart_ = clock_.seconds();
        receiverText_->setText(tr("Asking the receiver to average its position…"));
    });
    connect(setButton_, &QPushButton::clicked, this, &BaseStationView::setBase);
    connect(saveSite, &QPushButton::clicked, this, &BaseStationView::saveSite);
    connect(sitesButton_->menu(), &QMenu::aboutToShow, this, [this] {
        QMenu *menu = sitesButton_->menu();
        menu->clear();
        sites::SiteList list;
        QString why;
        if (!sites_ || !sites_->load(list, why) || list.empty())
            menu->addAction(why.isEmpty() ? tr("No sites yet") : why)->setEnabled(false);
        for (const sites::Site &s : list.sites()) {
            const QString name = QString::fromStdString(s.name);
            menu->addAction(name, this, [this, name] { pickSite(name); });
        }
    });
    if (engine_) {
        connect(engine_, &config::SettingsEngine::dialectChanged, this,
                &BaseStationView::onDialect);
        connect(engine_, &config::SettingsEngine::finished, this, &BaseStationView::onFinished);
        connect(engine_, &config::SettingsEngine::valuesChanged, this,
                &BaseStationView::showStatus);
    }
    connect(state_, &ReceiverStateModel::updated, this, &BaseStationView::onEpoch);
    onDialect();
}

void BaseStationView::setSiteStore(sites::SiteStore *store) {
    sites_ = store;
}

void BaseStationView::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    showStatus();
    showSurvey();
}

void BaseStationView::onDialect() {
    const Dialect *d = engine_ ? engine_->dialect() : nullptr;
    roles_ = d ? base::baseRoles(*d) : std::nullopt;
    // A Set waiting for the engine was for the receiver as it was; its status starts afresh.
    setWhenFree_ = readWhenFree_ = false;
    status_->setMinimumHeight(0);
    unsupported_->setVisible(!roles_);
    body_->setEnabled(roles_.has_value());
    if (!d)
        unsupported_->setText(tr("No receiver whose settings are known: a base station needs one "
                                 "that can be a base (the NV08C-RTK), identified on a link that "
                                 "takes commands."));
    else if (!roles_)
        unsupported_->setText(tr("The %1 cannot be a base station: its settings have no base mode.")
                                      .arg(QString::fromUtf8(d->displayName.data(),
                                                             qsizetype(d->displayName.size()))));
    if (!roles_) return;
    fillChoices();
    showStatus();
    // A replayed log or a receiver gpsd holds takes no commands: said, nothing to press.
    if (!engine_->canSend()) {
        unsupported_->setText(engine_->sendRefusal());
        unsupported_->show();
        body_->setEnabled(false);
    } else {
        readBase();
    }
}

void BaseStationView::fillChoices() {
    const config::SchemaTexts texts(roles_->dialect->id);
    station_->setSpecialValueText(tr("as it is"));
    if (const SettingDef *s = roles_->station)
        station_->setRange(-1, static_cast<int>(s->max.value_or(4095)));
    station_->setValue(-1);
    interval_->clear();
    interval_->addItem(tr("as they are"));
    if (const SettingDef *r = roles_->rtcmInterval)
        for (const SettingOption &o : r->options)
            interval_->addItem(
                    texts(o.label),
                    QString::fromUtf8(o.value.data(), qsizetype(o.value.size())).toInt());
    port_->clear();
    port_->addItem(tr("the ports as they are"), 0);
    for (int p : roles_->rtcmPorts())
        port_->addItem(tr("port %1 (%2)").arg(p).arg(texts(roles_->protocolOf(p)->label)), p);
    receiverButton_->setEnabled(roles_->canAverage());
    if (!roles_->canAverage())
        receiverText_->setText(tr("This receiver does not average its own position."));
}

void BaseStationView::readBase() {
    if (!roles_ || !engine_) return;
    if (!engine_->canSend()) return emit message(engine_->sendRefusal());
    if (engine_->isBusy()) {
        readWhenFree_ = true; // read when the operation in progress ends
        return;
    }
    readWhenFree_ = false;
    if (engine_->read(roles_->keys())) pending_ = Pending::Read;
}

void BaseStationView::runWhenFree() {
    if (!engine_ || engine_->isBusy() || !roles_) return; // still busy: its end calls again
    if (setWhenFree_) {
        setWhenFree_ = false;
        setBase();
    } else if (readWhenFree_) {
        readBase();
    }
}

void BaseStationView::onFinished(const config::OperationReport &r) {
    const Pending was = pending_;
    pending_ = Pending::None;
    if (was == Pending::Apply || was == Pending::Save) {
        if (was == Pending::Apply) verdicts_->clear();
        const config::SchemaTexts texts(roles_->dialect->id);
        for (const auto &c : r.checks) {
            // The setting as the form names it, then its key (what the console and docs say).
            const SettingDef *def = findSetting(roles_->dialect->settings, c.key);
            auto *item = new QListWidgetItem(
                    tr("%1, %2: %3 (%4)")
                            .arg(def ? texts(def->label) : QString(), QString::fromStdString(c.key),
                                 QString::fromStdString(c.wanted), config::verdictName(c.verdict)),
                    verdicts_);
            if (!config::isGood(c.verdict)) item->setForeground(QColor("#c62828"));
        }
        if (!r.error.isEmpty()) verdicts_->addItem(r.error);
        if (r.nothingToDo) verdicts_->addItem(tr("Every value was already in force."));
        if (was == Pending::Save)
            verdicts_->addItem(r.ok() ? tr("Saved to flash.") : tr("Not saved to flash."));
        const bool ok = r.ok();
        emit message(ok ? tr("Base settings verified.") : tr("Base settings not all verified."));
        if (was == Pending::Apply && ok && saveAfterApply_ &&
            engine_->runAction(ReceiverAction::SaveToFlash))
            pending_ = Pending::Save;
        saveAfterApply_ = false;
    } else if (was == Pending::ReadPosition) {
        const auto now = engine_->receiverValue(roles_->position->key);
        if (now && now != positionBefore_) {
            receiverSurveyStart_ = -1;
            receiverText_->setText(
                    tr("The receiver averaged its position: %1").arg(QString::fromStdString(*now)));
        }
    }
    showStatus();
    // After the finished() handlers of whoever ran it (one may start the next operation).
    if (setWhenFree_ || readWhenFree_)
        QMetaObject::invokeMethod(this, &BaseStationView::runWhenFree, Qt::QueuedConnection);
}

void BaseStationView::onEpoch() {
    const Epoch &e = state_->state().epoch;
    clock_.add(e.time);
    const double now = clock_.seconds();
    if (const auto position = e.position(); position && (surveying_ || receiverSurveyStart_ >= 0)) {
        survey_.add(now, *position);
        if (surveying_ && survey_.done()) {
            stopSurvey();
            emit message(tr("Survey-in done: accuracy %1")
                                 .arg(fmt::length(survey_.status().accuracy, 3, prefs_.units)));
        }
        showSurvey();
    }
    if (receiverSurveyStart_ >= 0 && roles_ && pending_ == Pending::None) {
        const double left = receiverMinutes_->value() * 60.0 - (now - receiverSurveyStart_);
        receiverText_->setText(
                left > 0 ? tr("The receiver averages its position: %1 s left").arg(std::ceil(left))
                         : tr("Waiting for the receiver's averaged position…"));
        // Its time is up: read its position every other second until it changes.
        if (left <= 0 && std::fmod(now, 2.0) < 0.25 && engine_->canSend() && !engine_->isBusy() &&
            engine_->read({std::string(roles_->position->key)}))
            pending_ = Pending::ReadPosition;
    }
    showStatus();
}

void BaseStationView::showStatus() {
    if (!roles_ || !engine_) return;
    const Epoch &e = state_->state().epoch;
    std::optional<base::OwnFix> own;
    if (const auto position = e.position())
        own = base::OwnFix{*position, std::string(toString(e.fix))};
    const base::BaseStatus s = base::baseStatus(*roles_, known(), own);
    QStringList lines;
    lines << tr("Role: %1").arg(roleText(s.meaning));
    if (s.positionGeodetic)
        lines << tr("Position: %1 %2, %3 (ECEF %4)")
                         .arg(fmt::latitude(s.positionGeodetic->latDeg, prefs_.coordinates),
                              fmt::longitude(s.positionGeodetic->lonDeg, prefs_.coordinates),
                              fmt::length(s.positionGeodetic->height, 3, prefs_.units),
                              ecefText(*s.position));
    QStringList sends;
    if (s.station) sends << tr("station %1").arg(QString::fromStdString(*s.station));
    if (s.rtcmInterval && roles_->rtcmInterval) {
        const config::SchemaTexts texts(roles_->dialect->id);
        for (const SettingOption &o : roles_->rtcmInterval->options)
            if (o.value == *s.rtcmInterval) sends << tr("observables: %1").arg(texts(o.label));
    }
    for (const auto &[port, meaning] : s.ports)
        if (meaning == OptionMeaning::Rtcm3) sends << tr("RTCM on port %1").arg(port);
    if (!sends.isEmpty()) lines << sends.join(QStringLiteral(" · "));
    if (s.distance)
        lines << tr("From its own fix: %1").arg(fmt::length(*s.distance, 2, prefs_.units));
    status_->setText(lines.join('\n'));
    // Its lines go while the settings are read again and come back: it keeps the height it had
    // on screen, so that what is below (Set base) does not move from under the pointer. (Not
    // measured while hidden: a label never laid out is 100 px wide, and ten lines tall there.)
    if (status_->isVisible()) {
        const int height = status_->heightForWidth(status_->width());
        if (height > status_->minimumHeight()) status_->setMinimumHeight(height);
    }
    warning_->setVisible(s.beyondThreshold);
    if (s.beyondThreshold)
        warning_->setText(tr("The base position is %1 from the receiver's own fix, past its "
                             "threshold of %2: it sends no corrections.")
                                  .arg(fmt::length(*s.distance, 0, prefs_.units),
                                       fmt::length(*s.threshold, 0, prefs_.units)));
}

void BaseStationView::showSurvey() {
    const base::SurveyStatus s = survey_.status();
    progress_->setValue(static_cast<int>(std::lround(survey_.progress() * 1000)));
    if (s.count == 0) {
        surveyText_->setText(surveying_ ? tr("Waiting for the receiver's fixes…") : QString());
        convergence_->setValues({}, {}, fmt::lengthUnit(prefs_.units),
                                fmt::lengthFactor(prefs_.units));
        return;
    }
    surveyText_->setText(
            tr("%n position(s) in %1 s. Mean %2 %3, %4.\nσ east %5, north %6, up %7; the mean "
               "known to %8.",
               nullptr, static_cast<int>(s.count))
                    .arg(std::lround(s.seconds))
                    .arg(fmt::latitude(s.mean.latDeg, prefs_.coordinates),
                         fmt::longitude(s.mean.lonDeg, prefs_.coordinates),
                         fmt::length(s.mean.height, 3, prefs_.units),
                         fmt::length(s.sigmaEast, 3, prefs_.units),
                         fmt::length(s.sigmaNorth, 3, prefs_.units),
                         fmt::length(s.sigmaUp, 3, prefs_.units),
                         fmt::length(s.accuracy, 3, prefs_.units)));
    // The running mean against the mean now.
    const auto &h = survey_.history();
    std::vector<double> horizontal, vertical;
    horizontal.reserve(h.size());
    vertical.reserve(h.size());
    const base::SurveyPoint &last = h.back();
    for (const base::SurveyPoint &p : h) {
        horizontal.push_back(std::hypot(p.east - last.east, p.north - last.north));
        vertical.push_back(p.up - last.up);
    }
    convergence_->setValues(std::move(horizontal), std::move(vertical),
                            fmt::lengthUnit(prefs_.units), fmt::lengthFactor(prefs_.units));
}

void BaseStationView::startSurvey() {
    if (!roles_) return;
    base::SurveyGoal goal;
    if (goal_->currentIndex() == 0)
        goal.seconds = goalValue_->value() * 60;
    else
        goal.accuracy = goalValue_->value();
    survey_ = base::SurveyIn(goal);
    receiverSurveyStart_ = -1;
    surveying_ = true;
    surveyButton_->setText(tr("Stop survey"));
    // A base reporting its set position gives no fix of its own: it is told to report its own.
    const base::BaseStatus now = base::baseStatus(*roles_, known(), std::nullopt);
    if (now.isBase() && now.nmeaPosition == base::meaningName(OptionMeaning::BasePosition) &&
        !engine_->isBusy()) {
        for (const SettingOption &o : roles_->nmeaPosition->options)
            if (o.meaning == OptionMeaning::OwnPosition &&
                engine_->apply({{std::string(roles_->nmeaPosition->key), std::string(o.value)}}))
                pending_ = Pending::Apply;
        emit message(tr("The receiver reported its set position: it now reports its own."));
    }
    showSurvey();
}

void BaseStationView::stopSurvey() {
    surveying_ = false;
    surveyButton_->setText(tr("Start survey"));
    showSurvey();
}

std::optional<wgs84::Ecef> BaseStationView::wantedPosition(QString *why) const {
    auto fail = [why](const QString &text) -> std::optional<wgs84::Ecef> {
        if (why) *why = text;
        return std::nullopt;
    };
    const Source source = static_cast<Source>(source_->currentIndex());
    if (source == Source::Survey) {
        if (survey_.status().count == 0) return fail(tr("No survey yet: start one first."));
        return survey_.status().meanEcef; // the antenna's own position
    }
    if (source == Source::ReceiverSurvey)
        return fail(tr("The receiver finds its position itself: start its survey instead."));
    const std::string text = position_->text().toStdString();
    std::string error;
    if (format_->currentIndex() == 1) {
        const auto p = base::ecefOf(text);
        if (!p) return fail(tr("Expected X, Y, Z in metres."));
        return base::raised(*p, antenna_->value());
    }
    auto g = base::parseGeodetic(text, error);
    if (!g) return fail(QString::fromStdString(error));
    if (msl_->isChecked()) {
        const auto sep = state_->state().epoch.geoidSep;
        if (!sep) return fail(tr("The receiver has not given its geoid separation yet."));
        g->height += *sep;
    }
    g->height += antenna_->value();
    return wgs84::toEcef(*g);
}

void BaseStationView::setBase() {
    if (!roles_ || !engine_) return;
    verdicts_->clear();
    QString why;
    const auto position = wantedPosition(&why);
    if (!position) return verdicts_->addItem(why);
    base::BaseRequest q;
    q.position = position;
    const base::BasePlan plan = planWithForm(q);
    if (!plan.ok()) return verdicts_->addItem(QString::fromStdString(plan.error));
    if (!engine_->canSend()) return verdicts_->addItem(engine_->sendRefusal());
    if (engine_->isBusy()) {
        setWhenFree_ = true;
        return verdicts_->addItem(tr("Waiting for the operation in progress on the receiver's "
                                     "settings to end; the base is set then."));
    }
    setWhenFree_ = false;
    saveAfterApply_ = saveFlash_->isChecked();
    if (engine_->apply(plan.values)) pending_ = Pending::Apply;
}

std::function<std::optional<std::string>(std::string_view)> BaseStationView::known() const {
    return [engine = engine_](std::string_view key) { return engine->receiverValue(key); };
}

base::BasePlan BaseStationView::planWithForm(base::BaseRequest q) const {
    if (station_->value() >= 0) q.station = station_->value();
    if (interval_->currentData().isValid()) q.rtcmInterval = interval_->currentData().toInt();
    if (port_->currentData().toInt() > 0) q.rtcmPort = port_->currentData().toInt();
    return base::planBase(*roles_, q, known());
}

void BaseStationView::pickSite(const QString &name) {
    if (!sites_) return;
    sites::SiteList list;
    QString why;
    if (!sites_->load(list, why)) return emit message(why);
    const sites::Site *s = list.find(name.toStdString());
    if (!s) return;
    source_->setCurrentIndex(static_cast<int>(Source::Known));
    format_->setCurrentIndex(0);
    msl_->setChecked(false);
    position_->setText(QStringLiteral("%1, %2, %3")
                               .arg(s->latDeg, 0, 'f', 9)
                               .arg(s->lonDeg, 0, 'f', 9)
                               .arg(s->height.value_or(0), 0, 'f', 4));
    antenna_->setValue(s->antennaHeight);
}

void BaseStationView::saveSite() {
    if (!sites_) return;
    QString why;
    const bool surveyed = static_cast<Source>(source_->currentIndex()) == Source::Survey;
    const auto p = wantedPosition(&why);
    if (!p) return emit message(why);
    const auto g = wgs84::toGeodetic(*p);
    if (!g) return;
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Save as site"), tr("Site name:"),
                                               QLineEdit::Normal, {}, &ok);
    if (!ok) return;
    sites::Site site = sites::surveyInSite(
            name.toStdString(), *g,
            surveyed ? std::optional<double>(survey_.status().accuracy) : std::nullopt,
            sites::todayUtc());
    if (!surveyed) site.method = "known";
    sites::SiteList list;
    if (!sites_->load(list, why)) return emit message(why);
    if (list.add(site, true) == sites::SiteList::AddResult::Invalid)
        return emit message(QString::fromStdString(sites::siteProblem(site)));
    emit message(sites_->save(list, why) ? tr("Site '%1' saved").arg(name) : why);
}

} // namespace gnss::ui
