#include "views/charts_view.h"
#include "models/refresh_intervals.h"

#include "views/chart_palette.h"

#include "models/receiver_state_model.h"
#include "style/gnss_style.h"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QListWidget>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace gnss::ui {

namespace {

using TS = TimeSeriesModel;

Constellation snrSystem(TS::Series s) {
    switch (s) {
    case TS::SnrGps: return Constellation::Gps;
    case TS::SnrGlonass: return Constellation::Glonass;
    case TS::SnrGalileo: return Constellation::Galileo;
    case TS::SnrBeiDou: return Constellation::BeiDou;
    case TS::SnrQzss: return Constellation::Qzss;
    case TS::SnrSbas: return Constellation::Sbas;
    case TS::SnrNavIC: return Constellation::NavIC;
    default: return Constellation::Unknown;
    }
}

// Okabe-Ito colours for the lines that are not a constellation's.
QColor lineColor(TS::Series s) {
    if (TS::group(s) == TS::Snr) return style::constellationColor(snrSystem(s));
    switch (s) {
    case TS::Pdop:
    case TS::SdLon: return style::lineColor(style::LineTone::Vermillion);
    case TS::SdHeight: return style::lineColor(style::LineTone::BluishGreen);
    case TS::FixKind: return style::lineColor(style::LineTone::ReddishPurple);
    default: return style::lineColor(style::LineTone::Blue);
    }
}

bool checkedByDefault(TS::Series s) {
    return s == TS::SatsUsed || s == TS::Hdop || s == TS::Pdop || s == TS::FixKind ||
           TS::group(s) == TS::Snr;
}

// Points relative to the newest epoch (x in `unitMs` units, negative = older), reduced to each
// bucket's min and max when there are more than `maxPoints`.
QList<QPointF> toPoints(const std::deque<TS::Sample> &d, qint64 latest, double unitMs,
                        int maxPoints, double factor) {
    QList<QPointF> out;
    const std::size_t n = d.size();
    auto pt = [&](const TS::Sample &s) {
        return QPointF((s.msecs - latest) / unitMs, s.value * factor);
    };
    if (n <= static_cast<std::size_t>(maxPoints)) {
        out.reserve(static_cast<qsizetype>(n));
        for (const auto &s : d) out.append(pt(s));
        return out;
    }
    const std::size_t bucket = (n + maxPoints / 2 - 1) / (maxPoints / 2);
    out.reserve(maxPoints + 2);
    for (std::size_t i = 0; i < n; i += bucket) {
        const std::size_t end = std::min(n, i + bucket);
        std::size_t lo = i, hi = i;
        for (std::size_t j = i; j < end; ++j) {
            if (d[j].value < d[lo].value) lo = j;
            if (d[j].value > d[hi].value) hi = j;
        }
        out.append(pt(d[std::min(lo, hi)]));
        if (lo != hi) out.append(pt(d[std::max(lo, hi)]));
    }
    return out;
}

// 1, 2 or 5 times a power of ten, at least x.
double niceStep(double x) {
    if (!(x > 0)) return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * p >= x * (1 - 1e-9)) return m * p;
    return 10 * p;
}

} // namespace

ChartsView::ChartsView(ReceiverStateModel *model, QWidget *parent)
    : QWidget(parent), series_(new TimeSeriesModel(this)), timer_(new QTimer(this)) {
    series_->attach(model);

    auto *side = new QWidget;
    auto *sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(new QLabel(tr("Series")));
    list_ = new QListWidget;
    list_->setObjectName("chartsSeriesList");
    for (int i = 0; i < TS::SeriesCount; ++i) {
        const auto s = static_cast<TS::Series>(i);
        auto *item = new QListWidgetItem(TS::label(s), list_);
        item->setData(Qt::UserRole, i);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(checkedByDefault(s) ? Qt::Checked : Qt::Unchecked);
    }
    sideLayout->addWidget(list_, 1);
    auto *win = new QHBoxLayout;
    win->addWidget(new QLabel(tr("Window")));
    window_ = new QSpinBox;
    window_->setObjectName("chartsWindow");
    window_->setRange(1, 60);
    window_->setValue(10);
    window_->setSuffix(tr(" min"));
    win->addWidget(window_, 1);
    sideLayout->addLayout(win);

    auto *charts = new QWidget;
    chartsLayout_ = new QVBoxLayout(charts);
    chartsLayout_->setContentsMargins(0, 0, 0, 0);
    chartsLayout_->setSpacing(2);
    chartsLayout_->addStretch(1);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(charts);

    auto *split = new QSplitter(Qt::Horizontal);
    split->addWidget(side);
    split->addWidget(scroll);
    split->setStretchFactor(1, 1);
    list_->setMinimumWidth(list_->sizeHintForColumn(0) + 8);
    split->setSizes({list_->minimumWidth(), 700});
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(split);

    series_->setWindowSeconds(window_->value() * 60.0);
    connect(window_, &QSpinBox::valueChanged, this, [this](int minutes) {
        series_->setWindowSeconds(minutes * 60.0);
        selectionChanged_ = true;
        redraw();
    });
    connect(list_, &QListWidget::itemChanged, this, [this] {
        selectionChanged_ = true;
        redraw();
    });
    startRefreshTimer(*timer_, kTrendRefreshMs, this, &ChartsView::redraw);
    redraw();
}

QStringList ChartsView::checkedSeries() const {
    QStringList keys;
    for (int i = 0; i < list_->count(); ++i)
        if (list_->item(i)->checkState() == Qt::Checked)
            keys << TS::key(static_cast<TS::Series>(list_->item(i)->data(Qt::UserRole).toInt()));
    return keys;
}

void ChartsView::setCheckedSeries(const QStringList &keys) {
    const QSignalBlocker block(list_);
    for (int i = 0; i < list_->count(); ++i) {
        const auto s = static_cast<TS::Series>(list_->item(i)->data(Qt::UserRole).toInt());
        list_->item(i)->setCheckState(keys.contains(TS::key(s)) ? Qt::Checked : Qt::Unchecked);
    }
    selectionChanged_ = true;
    redraw();
}

int ChartsView::windowMinutes() const {
    return window_->value();
}

void ChartsView::setDisplayPrefs(const DisplayPrefs &prefs) {
    units_ = prefs.units;
    for (int g = 0; g < TS::GroupCount; ++g)
        if (groups_[g].chart) groups_[g].chart->setTitle(TS::groupTitle(TS::Group(g), units_));
    drawnRevision_ = ~quint64(0); // redraw every line in the new unit (the charts stay)
    redraw();
}

void ChartsView::setWindowMinutes(int minutes) {
    window_->setValue(minutes);
}

ChartsView::GroupChart &ChartsView::ensureGroup(TS::Group g) {
    GroupChart &gc = groups_[g];
    if (gc.view) return gc;
    gc.chart = new QChart;
    gc.chart->setTitle(TS::groupTitle(g, units_));
    gc.chart->setMargins(QMargins(4, 2, 4, 2));
    // Up to seven constellations: their legend goes on top; other charts have room at the right.
    gc.chart->legend()->setAlignment(g == TS::Snr ? Qt::AlignTop : Qt::AlignRight);
    gc.chart->setAnimationOptions(QChart::NoAnimation);
    gc.x = new QValueAxis;
    gc.chart->addAxis(gc.x, Qt::AlignBottom);
    gc.x->setTickType(QValueAxis::TicksDynamic);
    gc.x->setTickAnchor(0.0);
    gc.x->setLabelFormat("%g");
    if (g == TS::Fix) {
        // Fix types by name; only the span the data covers, so the names fit (see redraw).
        auto *cat = new QCategoryAxis;
        cat->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
        gc.y = cat;
        gc.chart->legend()->hide();
    } else {
        auto *v = new QValueAxis;
        const char *format = "%.2f";
        switch (g) {
        case TS::Satellites: format = "%.0f"; break;
        case TS::Snr: format = "%.0f"; break;
        case TS::Dop: format = "%.1f"; break;
        case TS::Deviation: format = "%.3f"; break;
        default: break;
        }
        v->setLabelFormat(format);
        gc.y = v;
    }
    gc.chart->addAxis(gc.y, Qt::AlignLeft);
    gc.view = new QChartView(gc.chart);
    gc.view->setObjectName(QStringLiteral("chart_%1").arg(int(g)));
    gc.view->setRenderHint(QPainter::Antialiasing);
    gc.view->setMinimumHeight(g == TS::Snr || g == TS::Fix ? 220 : 180);
    // Keep the charts in group order above the trailing stretch.
    int at = 0;
    for (int i = 0; i < g; ++i)
        if (groups_[i].view) ++at;
    chartsLayout_->insertWidget(at, gc.view);
    return gc;
}

void ChartsView::rebuildCharts() {
    std::array<bool, TS::GroupCount> used{};
    for (int i = 0; i < list_->count(); ++i) {
        const auto s = static_cast<TS::Series>(list_->item(i)->data(Qt::UserRole).toInt());
        const bool on = list_->item(i)->checkState() == Qt::Checked;
        if (on) {
            used[TS::group(s)] = true;
            GroupChart &gc = ensureGroup(TS::group(s));
            if (!lines_[s]) {
                auto *line = new QLineSeries;
                line->setObjectName(QStringLiteral("series_") + TS::key(s));
                // In the SNR chart the title says "Mean SNR"; the legend names the system.
                line->setName(TS::group(s) == TS::Snr ? TS::key(s).mid(4) : TS::label(s));
                QPen pen(lineColor(s));
                pen.setWidthF(1.6);
                line->setPen(pen);
                gc.chart->addSeries(line);
                line->attachAxis(gc.x);
                line->attachAxis(gc.y);
                lines_[s] = line;
            }
        } else if (lines_[s]) {
            groups_[TS::group(s)].chart->removeSeries(lines_[s]);
            delete lines_[s];
            lines_[s] = nullptr;
        }
    }
    std::array<int, TS::GroupCount> lines{};
    for (int i = 0; i < TS::SeriesCount; ++i)
        if (lines_[i]) ++lines[TS::group(static_cast<TS::Series>(i))];
    for (int g = 0; g < TS::GroupCount; ++g) {
        if (!groups_[g].view) continue;
        groups_[g].view->setVisible(used[g]);
        // One line: the chart's title names it; the legend would only take room.
        groups_[g].chart->legend()->setVisible(g != TS::Fix && lines[g] > 1);
    }
    applyTheme();
}

void ChartsView::redraw() {
    if (!selectionChanged_ && series_->revision() == drawnRevision_) return;
    if (selectionChanged_) rebuildCharts();
    selectionChanged_ = false;
    drawnRevision_ = series_->revision();

    const double windowS = series_->windowSeconds();
    const bool minutes = windowS > 120.0;
    const double unitMs = minutes ? 60'000.0 : 1000.0;
    const double span = windowS * 1000.0 / unitMs;
    const qint64 latest = series_->latestMsecs();

    std::array<double, TS::GroupCount> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (int i = 0; i < TS::SeriesCount; ++i) {
        if (!lines_[i]) continue;
        const auto s = static_cast<TS::Series>(i);
        const QList<QPointF> pts = toPoints(series_->samples(s), latest, unitMs, kMaxPointsPerLine,
                                            TS::groupFactor(TS::group(s), units_));
        for (const QPointF &p : pts) {
            lo[TS::group(s)] = std::min(lo[TS::group(s)], p.y());
            hi[TS::group(s)] = std::max(hi[TS::group(s)], p.y());
        }
        lines_[i]->replace(pts);
        // No legend entry for a line without data (a constellation the receiver does not track).
        const auto markers = groups_[TS::group(s)].chart->legend()->markers(lines_[i]);
        for (QLegendMarker *m : markers) m->setVisible(!pts.isEmpty());
    }
    for (int g = 0; g < TS::GroupCount; ++g) {
        GroupChart &gc = groups_[g];
        if (!gc.view || !gc.view->isVisibleTo(this)) continue;
        gc.x->setRange(-span, 0.0);
        gc.x->setTickInterval(niceStep(span / 5.0));
        gc.x->setTitleText(minutes ? tr("minutes before the latest epoch")
                                   : tr("seconds before the latest epoch"));
        if (g == TS::Fix) {
            int a = std::isfinite(lo[g]) ? int(std::lround(lo[g])) : int(FixType::None);
            int b = std::isfinite(hi[g]) ? int(std::lround(hi[g])) : int(FixType::Fix3D);
            if (b - a < 2) a = std::max(0, b - 2), b = a + 2; // at least three names
            if (gc.fixLo != a || gc.fixHi != b) {
                // A fresh axis: Qt Charts 6.4 mislays the labels of a category axis whose
                // categories are replaced in place.
                gc.fixLo = a;
                gc.fixHi = b;
                auto *cat = new QCategoryAxis;
                cat->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
                cat->setStartValue(a - 0.5);
                for (int f = a; f <= b; ++f)
                    cat->append(style::fixTypeLabel(static_cast<FixType>(f)), f);
                cat->setRange(a - 0.5, b + 0.5);
                gc.chart->addAxis(cat, Qt::AlignLeft);
                // Qt Charts rescales an attached axis to the data after new points arrive
                // (later, from its own layout); the fix axis keeps the span its names were
                // made for.
                connect(cat, &QCategoryAxis::rangeChanged, this, [this, cat](qreal lo, qreal hi) {
                    const GroupChart &fc = groups_[TS::Fix];
                    if (lo != fc.fixLo - 0.5 || hi != fc.fixHi + 0.5)
                        cat->setRange(fc.fixLo - 0.5, fc.fixHi + 0.5);
                });
                for (QAbstractSeries *line : gc.chart->series()) {
                    line->detachAxis(gc.y);
                    line->attachAxis(cat);
                }
                gc.chart->removeAxis(gc.y);
                delete gc.y;
                gc.y = cat;
                applyTheme();
            }
            // Every time: attaching a line or replacing its points may rescale the axis to the
            // data.
            gc.y->setRange(a - 0.5, b + 0.5);
        }
        if (auto *v = qobject_cast<QValueAxis *>(gc.y)) {
            double a = lo[g], b = hi[g];
            if (!std::isfinite(a)) a = 0.0, b = 1.0;
            if (g == TS::Satellites || g == TS::Dop || g == TS::Deviation || g == TS::SpeedGroup)
                a = std::min(a, 0.0); // quantities that start at zero read better from zero
            if (b - a < 1e-9) a -= 0.5, b += 0.5;
            const double pad = (b - a) * 0.08;
            v->setRange(a < 0.0 || g == TS::Altitude || g == TS::Snr ? a - pad : a, b + pad);
            v->applyNiceNumbers();
        }
    }
}

void ChartsView::applyTheme() {
    for (GroupChart &gc : groups_)
        if (gc.chart)
            style::applyChartPalette(gc.chart, gc.view, {static_cast<QAbstractAxis *>(gc.x), gc.y},
                                     palette());
}

void ChartsView::changeEvent(QEvent *e) {
    if (e->type() == QEvent::PaletteChange) applyTheme();
    QWidget::changeEvent(e);
}

} // namespace gnss::ui
