#include "rtk_view.h"
#include "models/refresh_intervals.h"

#include "models/receiver_state_model.h"
#include "models/value_format.h"
#include "style/gnss_style.h"

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

// Angles read "40.61°", no space before the degree sign.
QString degrees(const std::optional<double> &v, int decimals) {
    return v ? fmt::number(v, decimals) + QChar(0x00B0) : fmt::dash();
}

// Counters can pass an int's range; "—" when not sent.
QString count(const std::optional<std::int64_t> &v) {
    return v ? QString::number(*v) : fmt::dash();
}

QGroupBox *box(const QString &title, QGridLayout **grid) {
    auto *g = new QGroupBox(title);
    *grid = new QGridLayout(g);
    (*grid)->setColumnStretch(1, 1);
    return g;
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

    auto *cols = new QGridLayout;
    QGridLayout *g = nullptr;

    auto *base = box(tr("Base station"), &g);
    correctionAge_ = addRow(g, tr("Correction age"), "rtkCorrectionAge");
    baseDistance_ = addRow(g, tr("Distance to base"), "rtkBaseDistance");
    baseId_ = addRow(g, tr("Base station id"), "rtkBaseId");
    rtcmTotal_ = addRow(g, tr("RTCM messages"), "rtkRtcmTotal");
    rtcmOk_ = addRow(g, tr("RTCM good"), "rtkRtcmOk");
    rtcmErrors_ = addRow(g, tr("RTCM errors"), "rtkRtcmErrors");
    cols->addWidget(base, 0, 0);

    auto *bl = box(tr("Baseline base \u2192 rover"), &g);
    blNorth_ = addRow(g, tr("North"), "rtkBaselineNorth");
    blEast_ = addRow(g, tr("East"), "rtkBaselineEast");
    blVertical_ = addRow(g, tr("Vertical"), "rtkBaselineVertical");
    blLength_ = addRow(g, tr("Length"), "rtkBaselineLength");
    blCourse_ = addRow(g, tr("Course"), "rtkBaselineCourse");
    blPitch_ = addRow(g, tr("Pitch"), "rtkBaselinePitch");
    cols->addWidget(bl, 0, 1);

    auto *hd = box(tr("Heading (antenna baseline)"), &g);
    heading_ = addRow(g, tr("Heading"), "rtkHeading");
    antPitch_ = addRow(g, tr("Pitch"), "rtkAntennaPitch");
    antLength_ = addRow(g, tr("Length"), "rtkAntennaLength");
    antNorth_ = addRow(g, tr("North"), "rtkAntennaNorth");
    antEast_ = addRow(g, tr("East"), "rtkAntennaEast");
    antVertical_ = addRow(g, tr("Vertical"), "rtkAntennaVertical");
    cols->addWidget(hd, 0, 2);

    auto *sd = box(tr("Standard deviations"), &g);
    sdLat_ = addRow(g, tr("Latitude"), "rtkSdLat");
    sdLon_ = addRow(g, tr("Longitude"), "rtkSdLon");
    sdHeight_ = addRow(g, tr("Height"), "rtkSdHeight");
    sdVelNorth_ = addRow(g, tr("Velocity north"), "rtkSdVelNorth");
    sdVelEast_ = addRow(g, tr("Velocity east"), "rtkSdVelEast");
    sdVelUp_ = addRow(g, tr("Velocity up"), "rtkSdVelUp");
    sdHeading_ = addRow(g, tr("Heading"), "rtkSdHeading");
    cols->addWidget(sd, 1, 0);

    auto *dop = box(tr("Receiver DOPs"), &g);
    gdop_ = addRow(g, tr("GDOP"), "rtkGdop");
    pdop_ = addRow(g, tr("PDOP"), "rtkPdop");
    hdop_ = addRow(g, tr("HDOP"), "rtkHdop");
    vdop_ = addRow(g, tr("VDOP"), "rtkVdop");
    tdop_ = addRow(g, tr("TDOP"), "rtkTdop");
    ndop_ = addRow(g, tr("NDOP"), "rtkNdop");
    edop_ = addRow(g, tr("EDOP"), "rtkEdop");
    cols->addWidget(dop, 1, 1);
    cols->setRowStretch(2, 1);
    pageLayout->addLayout(cols, 1);

    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(page);
    stack_->addWidget(scroll);
    stack_->setCurrentIndex(0);

    connect(threshold_, &QDoubleSpinBox::valueChanged, this, [this] { updateWatchdog(age_); });
    timer_->setInterval(kLiveRefreshMs);
    connect(timer_, &QTimer::timeout, this, &RtkView::poll);
    timer_->start();
    refresh();
}

QLabel *RtkView::addRow(QGridLayout *grid, const QString &name, const char *objectName) {
    const int row = grid->rowCount();
    grid->addWidget(new QLabel(name + QLatin1Char(':')), row, 0);
    auto *value = new QLabel(fmt::dash());
    value->setObjectName(QString::fromLatin1(objectName));
    value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    grid->addWidget(value, row, 1);
    return value;
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
        p.setColor(QPalette::WindowText, Qt::white);
        mode_->setPalette(p);
    } else {
        mode_->setText(fmt::dash());
        mode_->setPalette(QPalette()); // back to the theme's colours
    }

    const UnitSystem u = prefs_.units;
    const auto m = [u](const std::optional<double> &v) { return fmt::length(v, 3, u); };
    const auto ms = [u](const std::optional<double> &v) {
        return v ? fmt::number(*v * fmt::speedFactor(u), 3, fmt::speedUnit(u)) : fmt::dash();
    };
    rtcmTotal_->setText(count(r.rtcmTotal));
    rtcmOk_->setText(count(r.rtcmOk));
    rtcmErrors_->setText(count(r.rtcmErrors));
    baseDistance_->setText(m(r.baseDistance));
    baseId_->setText(r.baseStationId ? QString::number(*r.baseStationId) : fmt::dash());
    correctionAge_->setText(fmt::number(r.correctionAge, 1, tr("s")));

    blNorth_->setText(m(r.baseToRover.north));
    blEast_->setText(m(r.baseToRover.east));
    blVertical_->setText(m(r.baseToRover.vertical));
    blLength_->setText(m(r.baseToRover.length));
    blCourse_->setText(degrees(r.baseToRover.course, 2));
    blPitch_->setText(degrees(r.baseToRover.pitch, 2));

    heading_->setText(degrees(r.heading ? r.heading : r.antennas.course, 2));
    antPitch_->setText(degrees(r.antennas.pitch, 2));
    antLength_->setText(m(r.antennas.length));
    antNorth_->setText(m(r.antennas.north));
    antEast_->setText(m(r.antennas.east));
    antVertical_->setText(m(r.antennas.vertical));

    sdLat_->setText(m(r.sdLat));
    sdLon_->setText(m(r.sdLon));
    sdHeight_->setText(m(r.sdHeight));
    sdVelNorth_->setText(ms(r.sdVelNorth));
    sdVelEast_->setText(ms(r.sdVelEast));
    sdVelUp_->setText(ms(r.sdVelUp));
    sdHeading_->setText(degrees(r.sdHeading, 3));

    gdop_->setText(fmt::number(r.gdop, 2));
    pdop_->setText(fmt::number(r.pdop, 2));
    hdop_->setText(fmt::number(r.hdop, 2));
    vdop_->setText(fmt::number(r.vdop, 2));
    tdop_->setText(fmt::number(r.tdop, 2));
    ndop_->setText(fmt::number(r.ndop, 2));
    edop_->setText(fmt::number(r.edop, 2));

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
