#include "views/rtk_view.h"
#include "models/refresh_intervals.h"

#include "models/receiver_state_model.h"
#include "models/value_format.h"
#include "style/gnss_style.h"
#include "views/value_grid.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QStackedWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace gnss::ui {

namespace {

// A value of the panel written from the RTK state, in the user's units.
using RtkText = QString (*)(const RtkState &, UnitSystem);

struct RtkRow {
    const char *name;       // QT_TR_NOOP, in the panel's context
    const char *objectName; // of the value's label
    RtkText text;
};

struct RtkGroup {
    const char *title; // QT_TR_NOOP
    std::vector<RtkRow> rows;
};

QString metres(const std::optional<double> &v, UnitSystem u) {
    return fmt::length(v, 3, u);
}

QString speed(const std::optional<double> &v, UnitSystem u) {
    return v ? fmt::number(*v * fmt::speedFactor(u), 3, fmt::speedUnit(u)) : fmt::dash();
}

} // namespace

RtkView::RtkView(ReceiverStateModel *model, QWidget *parent)
    : QWidget(parent), model_(model), timer_(new QTimer(this)) {
    auto *outer = new QVBoxLayout(this);
    stack_ = new QStackedWidget;
    outer->addWidget(stack_);

    auto *none = new QLabel(tr("This receiver has not reported RTK information."));
    none->setObjectName("rtkUnavailable");
    none->setAlignment(Qt::AlignCenter);
    none->setWordWrap(true);
    stack_->addWidget(none);

    auto *page = new QWidget;
    auto *pageLayout = new QVBoxLayout(page);

    // Mode badge and watchdog on top: what an engineer glances at.
    auto *top = new QHBoxLayout;
    mode_ = new QLabel(fmt::dash());
    mode_->setObjectName("rtkMode");
    mode_->setAlignment(Qt::AlignCenter);
    mode_->setMinimumWidth(110);
    mode_->setMargin(4);
    mode_->setAutoFillBackground(true);
    QFont bf = mode_->font();
    bf.setBold(true);
    mode_->setFont(bf);
    top->addWidget(new QLabel(tr("Mode:")));
    top->addWidget(mode_);
    top->addSpacing(16);
    watchdog_ = new QLabel(fmt::dash());
    watchdog_->setObjectName("rtkWatchdog");
    watchdog_->setFont(bf);
    top->addWidget(watchdog_);
    top->addStretch(1);
    top->addWidget(new QLabel(tr("Alarm when corrections are older than")));
    threshold_ = new QDoubleSpinBox;
    threshold_->setObjectName("rtkAgeThreshold");
    threshold_->setRange(0.1, 3600.0);
    threshold_->setDecimals(1);
    threshold_->setValue(10.0);
    threshold_->setSuffix(tr(" s"));
    top->addWidget(threshold_);
    pageLayout->addLayout(top);

    // The groups, three to a row, each a grid of "name: value" rows, and how each value is
    // written from the RTK state (S) in the user's units (U).
    using S = const RtkState &;
    using U = UnitSystem;
    const RtkGroup groups[] = {
            {QT_TR_NOOP("Base station"),
             {{QT_TR_NOOP("Correction age"), "rtkCorrectionAge",
               [](S r, U) { return fmt::number(r.correctionAge, 1, tr("s")); }},
              {QT_TR_NOOP("Distance to base"), "rtkBaseDistance",
               [](S r, U u) { return metres(r.baseDistance, u); }},
              {QT_TR_NOOP("Base station id"), "rtkBaseId",
               [](S r, U) { return fmt::integer(r.baseStationId); }},
              {QT_TR_NOOP("RTCM messages"), "rtkRtcmTotal",
               [](S r, U) { return fmt::count(r.rtcmTotal); }},
              {QT_TR_NOOP("RTCM good"), "rtkRtcmOk", [](S r, U) { return fmt::count(r.rtcmOk); }},
              {QT_TR_NOOP("RTCM errors"), "rtkRtcmErrors",
               [](S r, U) { return fmt::count(r.rtcmErrors); }}}},
            {QT_TR_NOOP("Baseline base \u2192 rover"),
             {{QT_TR_NOOP("North"), "rtkBaselineNorth",
               [](S r, U u) { return metres(r.baseToRover.north, u); }},
              {QT_TR_NOOP("East"), "rtkBaselineEast",
               [](S r, U u) { return metres(r.baseToRover.east, u); }},
              {QT_TR_NOOP("Vertical"), "rtkBaselineVertical",
               [](S r, U u) { return metres(r.baseToRover.vertical, u); }},
              {QT_TR_NOOP("Length"), "rtkBaselineLength",
               [](S r, U u) { return metres(r.baseToRover.length, u); }},
              {QT_TR_NOOP("Course"), "rtkBaselineCourse",
               [](S r, U) { return fmt::angle(r.baseToRover.course, 2); }},
              {QT_TR_NOOP("Pitch"), "rtkBaselinePitch",
               [](S r, U) { return fmt::angle(r.baseToRover.pitch, 2); }}}},
            {QT_TR_NOOP("Heading (antenna baseline)"),
             {{QT_TR_NOOP("Heading"), "rtkHeading",
               [](S r, U) { return fmt::angle(r.heading ? r.heading : r.antennas.course, 2); }},
              {QT_TR_NOOP("Pitch"), "rtkAntennaPitch",
               [](S r, U) { return fmt::angle(r.antennas.pitch, 2); }},
              {QT_TR_NOOP("Length"), "rtkAntennaLength",
               [](S r, U u) { return metres(r.antennas.length, u); }},
              {QT_TR_NOOP("North"), "rtkAntennaNorth",
               [](S r, U u) { return metres(r.antennas.north, u); }},
              {QT_TR_NOOP("East"), "rtkAntennaEast",
               [](S r, U u) { return metres(r.antennas.east, u); }},
              {QT_TR_NOOP("Vertical"), "rtkAntennaVertical",
               [](S r, U u) { return metres(r.antennas.vertical, u); }}}},
            {QT_TR_NOOP("Standard deviations"),
             {{QT_TR_NOOP("Latitude"), "rtkSdLat", [](S r, U u) { return metres(r.sdLat, u); }},
              {QT_TR_NOOP("Longitude"), "rtkSdLon", [](S r, U u) { return metres(r.sdLon, u); }},
              {QT_TR_NOOP("Height"), "rtkSdHeight", [](S r, U u) { return metres(r.sdHeight, u); }},
              {QT_TR_NOOP("Velocity north"), "rtkSdVelNorth",
               [](S r, U u) { return speed(r.sdVelNorth, u); }},
              {QT_TR_NOOP("Velocity east"), "rtkSdVelEast",
               [](S r, U u) { return speed(r.sdVelEast, u); }},
              {QT_TR_NOOP("Velocity up"), "rtkSdVelUp",
               [](S r, U u) { return speed(r.sdVelUp, u); }},
              {QT_TR_NOOP("Heading"), "rtkSdHeading",
               [](S r, U) { return fmt::angle(r.sdHeading, 3); }}}},
            {QT_TR_NOOP("Receiver DOPs"),
             {{QT_TR_NOOP("GDOP"), "rtkGdop", [](S r, U) { return fmt::number(r.gdop, 2); }},
              {QT_TR_NOOP("PDOP"), "rtkPdop", [](S r, U) { return fmt::number(r.pdop, 2); }},
              {QT_TR_NOOP("HDOP"), "rtkHdop", [](S r, U) { return fmt::number(r.hdop, 2); }},
              {QT_TR_NOOP("VDOP"), "rtkVdop", [](S r, U) { return fmt::number(r.vdop, 2); }},
              {QT_TR_NOOP("TDOP"), "rtkTdop", [](S r, U) { return fmt::number(r.tdop, 2); }},
              {QT_TR_NOOP("NDOP"), "rtkNdop", [](S r, U) { return fmt::number(r.ndop, 2); }},
              {QT_TR_NOOP("EDOP"), "rtkEdop", [](S r, U) { return fmt::number(r.edop, 2); }}}},
    };
    auto *cols = new QGridLayout;
    int place = 0;
    for (const RtkGroup &group : groups) {
        QGridLayout *grid = nullptr;
        cols->addWidget(valueGroup(tr(group.title), grid), place / 3, place % 3);
        ++place;
        for (const RtkRow &row : group.rows)
            values_.push_back({addValueRow(grid, tr(row.name), row.objectName), row.text});
    }
    cols->setRowStretch(2, 1);
    pageLayout->addLayout(cols, 1);

    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(page);
    stack_->addWidget(scroll);
    stack_->setCurrentIndex(0);
    correctionAge_ = findChild<QLabel *>(QStringLiteral("rtkCorrectionAge"));

    connect(threshold_, &QDoubleSpinBox::valueChanged, this, [this] { updateWatchdog(age_); });
    startRefreshTimer(*timer_, kLiveRefreshMs, this, &RtkView::poll);
    refresh();
}

double RtkView::correctionAgeThreshold() const {
    return threshold_->value();
}

void RtkView::setCorrectionAgeThreshold(double seconds) {
    threshold_->setValue(seconds);
}

QColor RtkView::alarmColor() {
    return style::errorColor();
}

void RtkView::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    refresh();
}

void RtkView::poll() {
    if (model_->epochCount() != shownEpochs_) refresh();
}

void RtkView::refresh() {
    shownEpochs_ = model_->epochCount();
    const RtkState &r = model_->state().rtk;
    if (r.seen != available_) {
        available_ = r.seen;
        stack_->setCurrentIndex(available_ ? 1 : 0);
        emit availabilityChanged(available_);
    }

    // Mode: the sentence's mode letter in the fix badge's words and colours.
    if (r.mode) {
        QString word;
        switch (*r.mode) {
        case 'A': word = tr("Autonomous"); break;
        case 'D': word = tr("Differential"); break;
        case 'F': word = style::fixTypeLabel(FixType::RtkFloat); break;
        case 'R': word = style::fixTypeLabel(FixType::RtkFixed); break;
        case 'E': word = style::fixTypeLabel(FixType::Estimated); break;
        case 'M': word = style::fixTypeLabel(FixType::Manual); break;
        case 'N': word = style::fixTypeLabel(FixType::None); break;
        default: word = QString(QLatin1Char(*r.mode)); break;
        }
        mode_->setText(word);
        QPalette p;
        p.setColor(QPalette::Window, style::fixTypeColor(fixTypeFromModeIndicator(*r.mode)));
        p.setColor(QPalette::WindowText, style::badgeTextColor());
        mode_->setPalette(p);
    } else {
        mode_->setText(fmt::dash());
        mode_->setPalette(QPalette()); // back to the theme's colours
    }

    for (const Value &value : values_) value.label->setText(value.text(r, prefs_.units));

    updateWatchdog(r.correctionAge);
}

void RtkView::updateWatchdog(std::optional<double> age) {
    age_ = age;
    const bool late = age && *age > threshold_->value();
    QPalette p; // an empty palette inherits the theme's colours; only the alarm overrides
    if (late) p.setColor(QPalette::WindowText, alarmColor());
    correctionAge_->setPalette(p);
    watchdog_->setPalette(p);
    QFont f = correctionAge_->font();
    f.setBold(late);
    correctionAge_->setFont(f);
    if (!age)
        watchdog_->setText(tr("Correction age: %1").arg(fmt::dash()));
    else if (late)
        watchdog_->setText(tr("Corrections too old: %1 s > %2 s")
                                   .arg(*age, 0, 'f', 1)
                                   .arg(threshold_->value(), 0, 'f', 1));
    else
        watchdog_->setText(tr("Corrections OK: %1 s").arg(*age, 0, 'f', 1));
    if (late != late_) {
        late_ = late;
        emit correctionsLateChanged(late_);
    }
}

} // namespace gnss::ui
