#include "views/fix_view.h"
#include "models/refresh_intervals.h"

#include "models/receiver_state_model.h"
#include "models/value_format.h"
#include "style/gnss_style.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace gnss::ui {

FixView::FixView(ReceiverStateModel *model, QWidget *parent) : QWidget(parent), model_(model) {
    setObjectName("fixView");
    auto *outer = new QVBoxLayout(this);
    auto *top = new QHBoxLayout;
    badge_ = new QLabel(this);
    badge_->setObjectName("fixBadge");
    badge_->setAlignment(Qt::AlignCenter);
    badge_->setMinimumWidth(120);
    QFont bf = badge_->font();
    bf.setBold(true);
    bf.setPointSizeF(bf.pointSizeF() * 1.3);
    badge_->setFont(bf);
    top->addWidget(badge_);
    top->addStretch();
    format_ = new QComboBox(this);
    format_->setObjectName("coordinateFormat");
    format_->addItems({tr("Degrees"), tr("Deg min"), tr("Deg min sec")});
    format_->setToolTip(tr("How coordinates are written (also in Preferences)"));
    connect(format_, &QComboBox::activated, this, [this](int i) {
        DisplayPrefs p = prefs_;
        p.coordinates = CoordinateFormat(i);
        setDisplayPrefs(p);
        emit coordinateFormatChosen(p.coordinates);
    });
    top->addWidget(format_);
    outer->addLayout(top);
    grid_ = new QGridLayout;
    outer->addLayout(grid_);
    outer->addStretch();
    lat_ = addRow(tr("Latitude"), "fixLatitude");
    lon_ = addRow(tr("Longitude"), "fixLongitude");
    altMsl_ = addRow(tr("Altitude (sea level)"), "fixAltMsl");
    altEll_ = addRow(tr("Altitude (ellipsoid)"), "fixAltEllipsoid");
    sats_ = addRow(tr("Satellites used / in view"), "fixSatellites");
    dops_ = addRow(tr("PDOP / HDOP / VDOP"), "fixDops");
    utc_ = addRow(tr("Time"), "fixUtc");
    speed_ = addRow(tr("Speed"), "fixSpeed");
    course_ = addRow(tr("Course"), "fixCourse");
    corrAge_ = addRow(tr("Age of corrections"), "fixCorrectionAge");
    base_ = addRow(tr("Base station"), "fixBaseStation");
    connect(model_, &ReceiverStateModel::updated, this, [this] { dirty_ = true; });
    startRefreshTimer(timer_, kLiveRefreshMs, this, [this] {
        if (dirty_ && isVisible()) refresh();
    });
    refresh();
}

QLabel *FixView::addRow(const QString &name, const QString &objectName) {
    const int row = grid_->rowCount();
    auto *n = new QLabel(name, this);
    n->setForegroundRole(QPalette::PlaceholderText);
    auto *v = new QLabel(fmt::dash(), this);
    v->setObjectName(objectName);
    v->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont f = v->font();
    f.setFamily(QStringLiteral("monospace"));
    f.setStyleHint(QFont::TypeWriter);
    v->setFont(f);
    grid_->addWidget(n, row, 0);
    grid_->addWidget(v, row, 1);
    return v;
}

void FixView::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    format_->setCurrentIndex(int(prefs.coordinates));
    refresh();
}

void FixView::refresh() {
    dirty_ = false;
    const Epoch &e = model_->state().epoch;
    const bool any = model_->epochCount() > 0;
    const FixType fix = any ? e.fix : FixType::None;
    QString text = any ? style::fixTypeLabel(fix) : tr("No data");
    if (!e.fixNote.empty()) text += QStringLiteral(" · ") + QString::fromStdString(e.fixNote);
    badge_->setText(text);
    const QColor c = style::fixTypeColor(fix);
    badge_->setStyleSheet(QStringLiteral("QLabel { %1 }").arg(style::badgeCss(c, 6, "4px 10px")));
    const UnitSystem units = prefs_.units;
    lat_->setText(fmt::latitude(e.lat, prefs_.coordinates));
    lon_->setText(fmt::longitude(e.lon, prefs_.coordinates));
    altMsl_->setText(fmt::length(e.altMsl, 3, units));
    altEll_->setText(fmt::length(e.altEllipsoid(), 3, units));
    int inView = 0;
    {
        QSet<quint64> seen;
        for (const auto &s : e.satellites)
            if (!seen.contains((quint64(quint8(s.sat.system)) << 32) | quint32(s.sat.prn))) {
                seen.insert((quint64(quint8(s.sat.system)) << 32) | quint32(s.sat.prn));
                ++inView;
            }
    }
    // In view: "—" when the receiver sends no satellites in view (no GSV), never 0.
    sats_->setText(QStringLiteral("%1 / %2").arg(
            fmt::integer(e.satsUsed), any && inView > 0 ? QString::number(inView) : fmt::dash()));
    dops_->setText(
            QStringLiteral("%1 / %2 / %3")
                    .arg(fmt::number(e.pdop, 2), fmt::number(e.hdop, 2), fmt::number(e.vdop, 2)));
    utc_->setText(fmt::time(e.date, e.time, prefs_.time));
    speed_->setText(fmt::speed(
            e.sogKnots ? std::optional(*e.sogKnots * 1852.0 / 3600.0) : std::nullopt, units));
    course_->setText(e.cog ? fmt::number(e.cog, 1) + QStringLiteral("°") : fmt::dash());
    const auto age = e.dgpsAge ? e.dgpsAge : model_->state().rtk.correctionAge;
    corrAge_->setText(fmt::number(age, 1, tr("s")));
    base_->setText(fmt::integer(e.dgpsStation));
}

} // namespace gnss::ui
