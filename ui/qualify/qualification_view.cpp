// The Qualification dock's widget: the campaign's form, progress, results, CDF, runs, accuracy.
#include "qualify/qualification_view.h"

#include "qualify/accuracy_panel.h"
#include "qualify/qualify_plots.h"
#include "widgets/read_only_table.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace gnss::ui {

namespace {

QString secondsText(const std::optional<double> &s) {
    return s ? QString::number(*s, 'f', 1) : fmt::dash();
}

QString startName(ReceiverAction a) {
    switch (a) {
    case ReceiverAction::ColdStart: return QualificationView::tr("cold");
    case ReceiverAction::WarmStart: return QualificationView::tr("warm");
    case ReceiverAction::HotStart: return QualificationView::tr("hot");
    default: break;
    }
    return QString::fromLatin1(toString(a).data(), qsizetype(toString(a).size()));
}

QString outcomeName(qualify::RunOutcome o) {
    switch (o) {
    case qualify::RunOutcome::Fixed: return QualificationView::tr("fixed");
    case qualify::RunOutcome::TimedOut: return QualificationView::tr("timed out");
    case qualify::RunOutcome::Lost: return QualificationView::tr("link lost");
    }
    return {};
}

void setRow(QTableWidget *t, int row, const QStringList &cells) {
    for (int c = 0; c < cells.size(); ++c) {
        auto *item = new QTableWidgetItem(cells[c]);
        if (c > 1) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        t->setItem(row, c, item);
    }
}

QSpinBox *spin(QWidget *parent, const char *name, int min, int max, int value,
               const QString &suffix) {
    auto *s = new QSpinBox(parent);
    s->setObjectName(name);
    s->setRange(min, max);
    s->setValue(value);
    s->setSuffix(suffix);
    return s;
}

} // namespace

QualificationView::QualificationView(QWidget *parent) : QWidget(parent) {
    auto *outer = new QHBoxLayout(this);
    outer->setContentsMargins(2, 2, 2, 2);
    auto *form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // What each receiver's campaign does now, first (the form scrolls; the results keep the
    // dock's height); the bar is the tabs' corner.
    progressText_ = new QLabel(tr("No campaign yet."), this);
    progressText_->setObjectName("qualifyProgress");
    progressText_->setWordWrap(true);
    progressText_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(progressText_);
    scope_ = new QComboBox(this);
    scope_->setObjectName("qualifyScope");
    scope_->addItem(tr("The selected receiver"));
    scope_->addItem(tr("Every receiver, at once"));
    form->addRow(tr("On:"), scope_);
    auto *starts = new QHBoxLayout;
    cold_ = new QCheckBox(tr("Cold"), this);
    warm_ = new QCheckBox(tr("Warm"), this);
    hot_ = new QCheckBox(tr("Hot"), this);
    cold_->setObjectName("qualifyCold");
    warm_->setObjectName("qualifyWarm");
    hot_->setObjectName("qualifyHot");
    cold_->setChecked(true);
    for (QCheckBox *c : {cold_, warm_, hot_}) starts->addWidget(c);
    starts->addStretch();
    form->addRow(tr("Starts:"), starts);
    runsCount_ = spin(this, "qualifyRuns", 1, 1000, 10, {});
    form->addRow(tr("Runs of each:"), runsCount_);
    timeout_ = spin(this, "qualifyTimeout", 5, 3600, 180, tr(" s"));
    timeout_->setToolTip(tr("A run without a 3D fix after this long is counted as a timeout"));
    form->addRow(tr("Timeout:"), timeout_);
    pause_ = spin(this, "qualifyPause", 0, 3600, 5, tr(" s"));
    form->addRow(tr("Pause:"), pause_);
    hold_ = spin(this, "qualifyHold", 0, 3600, 30, tr(" s"));
    hold_->setToolTip(tr("Before a warm or hot start the receiver holds a 3D fix this long, so "
                         "that it has its ephemerides"));
    form->addRow(tr("Hold fix:"), hold_);
    limits_ = new QLineEdit(this);
    limits_->setObjectName("qualifyLimits");
    limits_->setPlaceholderText(tr("cold:mean<=60, hot:p95<=15"));
    limits_->setToolTip(tr("Limits to pass, separated by commas: START:STATISTIC<=SECONDS, the "
                           "statistic one of mean, median, p90, p95, max"));
    form->addRow(tr("Limits:"), limits_);
    auto *buttons = new QHBoxLayout;
    start_ = new QPushButton(tr("Start"), this);
    cancel_ = new QPushButton(tr("Cancel"), this);
    report_ = new QPushButton(tr("Save report…"), this);
    start_->setObjectName("qualifyStart");
    cancel_->setObjectName("qualifyCancel");
    report_->setObjectName("qualifyReport");
    cancel_->setEnabled(false);
    report_->setEnabled(false);
    for (QPushButton *b : {start_, cancel_, report_}) buttons->addWidget(b);
    form->addRow(buttons);
    message_ = new QLabel(this);
    message_->setObjectName("qualifyMessage");
    message_->setWordWrap(true);
    message_->setStyleSheet(QStringLiteral("color: #c62828"));
    form->addRow(message_);
    // In a scroll area: the dock stays as short as a laptop's bottom row allows.
    auto *formBox = new QWidget;
    formBox->setLayout(form);
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(formBox);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setMinimumWidth(std::min(formBox->sizeHint().width() + 24, 340));
    scroll->setMaximumWidth(420);
    outer->addWidget(scroll);

    tabs_ = new QTabWidget(this);
    bar_ = new QProgressBar(tabs_);
    bar_->setRange(0, 1);
    bar_->setValue(0);
    bar_->setFormat(QStringLiteral("%v / %m"));
    bar_->setToolTip(tr("Runs done of the campaign's runs"));
    bar_->setFixedWidth(bar_->fontMetrics().horizontalAdvance(QStringLiteral("0000 / 0000")) + 40);
    tabs_->setCornerWidget(bar_, Qt::TopRightCorner);
    results_ = readOnlyTable(13, "qualifyResults", tabs_);
    results_->setHorizontalHeaderLabels({tr("Receiver"), tr("Start"), tr("Runs"), tr("Fixed"),
                                         tr("Timeouts"), tr("Lost"), tr("Mean"), tr("Median"),
                                         tr("P90"), tr("P95"), tr("Min"), tr("Max"), tr("Limits")});
    results_->setToolTip(tr("Times to a 3D fix in seconds, of the runs that fixed"));
    tabs_->addTab(results_, tr("Results"));
    cdf_ = new CdfPlot(tabs_);
    cdf_->setObjectName("qualifyCdf");
    tabs_->addTab(cdf_, tr("CDF"));
    runs_ = readOnlyTable(12, "qualifyRuns", tabs_);
    runs_->setHorizontalHeaderLabels({tr("Receiver"), tr("Start"), tr("Run"), tr("Outcome"),
                                      tr("Position"), tr("2D"), tr("3D (TTFF)"), tr("DGNSS"),
                                      tr("RTK float"), tr("RTK fixed"), tr("Satellites"),
                                      tr("Distance")});
    tabs_->addTab(runs_, tr("Runs"));
    accuracy_ = new AccuracyPanel(tabs_);
    accuracy_->setObjectName("qualifyAccuracy");
    tabs_->addTab(accuracy_, tr("Accuracy"));
    outer->addWidget(tabs_, 1);

    connect(start_, &QPushButton::clicked, this, [this] {
        if (const auto r = request()) emit startRequested(*r);
    });
    connect(cancel_, &QPushButton::clicked, this, &QualificationView::cancelRequested);
    connect(report_, &QPushButton::clicked, this, &QualificationView::reportRequested);
    setReceiverCount(1);
}

void QualificationView::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    accuracy_->setUnits(prefs.units);
}

void QualificationView::setRunning(bool running) {
    start_->setEnabled(!running);
    cancel_->setEnabled(running);
    for (QWidget *w : std::initializer_list<QWidget *>{scope_, cold_, warm_, hot_, runsCount_,
                                                       timeout_, pause_, hold_, limits_})
        w->setEnabled(!running);
}

void QualificationView::setReceiverCount(int n) {
    scope_->setEnabled(n > 1 && start_->isEnabled());
    if (n <= 1) scope_->setCurrentIndex(0);
}

void QualificationView::setProgress(const QStringList &lines, int done, int total,
                                    double secondsLeft) {
    QString text = lines.join(QLatin1Char('\n'));
    if (secondsLeft >= 0)
        text += QLatin1Char('\n') + tr("Run %1 of %2; about %3 min left")
                                            .arg(done)
                                            .arg(total)
                                            .arg(QString::number(secondsLeft / 60.0, 'f', 1));
    progressText_->setText(text);
    bar_->setRange(0, std::max(1, total));
    bar_->setValue(std::min(done, std::max(1, total)));
}

void QualificationView::setResults(const std::vector<qualify::ReportReceiver> &receivers,
                                   const std::vector<qualify::Limit> &limits) {
    results_->setRowCount(0);
    runs_->setRowCount(0);
    bool any = false;
    for (const qualify::ReportReceiver &rx : receivers) {
        const auto verdicts = qualify::checkLimits(limits, rx.runs);
        for (const qualify::StartStats &s : qualify::statsOf(rx.runs)) {
            QStringList passes;
            for (const qualify::LimitResult &v : verdicts)
                if (v.limit.start == s.start)
                    passes << tr("%1 %2 ≤ %3 s: %4")
                                      .arg(QString::fromStdString(
                                                   std::string(toString(v.limit.stat))),
                                           secondsText(v.value),
                                           QString::number(v.limit.maxSeconds),
                                           v.pass ? tr("pass") : tr("FAIL"));
            const bool fixed = s.fixed > 0;
            auto stat = [&](double v) { return fixed ? secondsText(v) : fmt::dash(); };
            const int row = results_->rowCount();
            results_->insertRow(row);
            setRow(results_, row,
                   {rx.name, startName(s.start), QString::number(s.runs), QString::number(s.fixed),
                    QString::number(s.timeouts), QString::number(s.lost), stat(s.ttff.mean),
                    stat(s.ttff.median), stat(s.p90), stat(s.ttff.p95), stat(s.ttff.min),
                    stat(s.ttff.max), passes.join(QStringLiteral("; "))});
            bool pass = true;
            for (const auto &v : verdicts)
                if (v.limit.start == s.start) pass = pass && v.pass;
            if (!passes.isEmpty())
                results_->item(row, 12)->setForeground(pass ? QColor(0x2E, 0x7D, 0x32)
                                                            : QColor(0xC6, 0x28, 0x28));
        }
        for (const qualify::TtffRun &r : rx.runs) {
            any = true;
            const int row = runs_->rowCount();
            runs_->insertRow(row);
            setRow(runs_, row,
                   {rx.name, startName(r.start), QString::number(r.index), outcomeName(r.outcome),
                    secondsText(r.position), secondsText(r.fix2d), secondsText(r.fix3d),
                    secondsText(r.dgnss), secondsText(r.rtkFloat), secondsText(r.rtkFixed),
                    r.satellitesAtFix ? QString::number(*r.satellitesAtFix) : fmt::dash(),
                    r.distanceM ? fmt::length(*r.distanceM, 1, prefs_.units) : fmt::dash()});
        }
    }
    results_->resizeColumnsToContents();
    runs_->resizeColumnsToContents();
    cdf_->setSeries(qualify::cdfSeriesOf(receivers));
    report_->setEnabled(any);
}

void QualificationView::showMessage(const QString &text) {
    message_->setText(text);
}

QString QualificationView::message() const {
    return message_->text();
}

std::optional<QualificationRequest> QualificationView::request() {
    QualificationRequest r;
    if (cold_->isChecked()) r.plan.starts.push_back(ReceiverAction::ColdStart);
    if (warm_->isChecked()) r.plan.starts.push_back(ReceiverAction::WarmStart);
    if (hot_->isChecked()) r.plan.starts.push_back(ReceiverAction::HotStart);
    if (r.plan.starts.empty()) {
        showMessage(tr("Choose at least one kind of start."));
        return std::nullopt;
    }
    r.plan.runs = runsCount_->value();
    r.plan.timeoutMs = timeout_->value() * 1000;
    r.plan.pauseMs = pause_->value() * 1000;
    r.plan.holdMs = hold_->value() * 1000;
    for (const QString &part : limits_->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        std::string why;
        const auto l = qualify::Limit::parse(part.trimmed().toStdString(), why);
        if (!l) {
            showMessage(tr("A limit is not understood: %1").arg(QString::fromStdString(why)));
            return std::nullopt;
        }
        r.limits.push_back(*l);
    }
    if (!accuracy_->referenceValid()) {
        showMessage(tr("The reference point (Accuracy tab) is not a point."));
        return std::nullopt;
    }
    if (const auto p = accuracy_->reference()) r.plan.reference = std::pair(p->latDeg, p->lonDeg);
    r.allReceivers = scope_->currentIndex() == 1;
    showMessage({});
    return r;
}

} // namespace gnss::ui
