#include "views/deviation_view.h"
#include "models/refresh_intervals.h"

#include "models/receiver_state_model.h"
#include "models/value_format.h"
#include "style/gnss_style.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <set>

namespace gnss::ui {

namespace {

// 1, 2 or 5 times a power of ten, at least x.
double niceCeil(double x) {
    if (!(x > 0)) return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= x * (1 - 1e-9)) return m * p;
    return 10 * p;
}

// A length in metres, in the user's units: 3 decimals below 100, 1 above.
QString metres(double v, UnitSystem u) {
    const double shown = v * fmt::lengthFactor(u);
    return fmt::length(v, std::fabs(shown) < 100.0 ? 3 : 1, u);
}

} // namespace

// The plot itself: squares the east/north axes, autoscales to the points and circles.
class DeviationView::Canvas : public QWidget {
public:
    UnitSystem units = UnitSystem::Metric; // of the axes and the scale bar
    explicit Canvas(const PositionScatter *s, QWidget *parent) : QWidget(parent), s_(s) {
        setObjectName("deviationCanvas");
        setMinimumSize(200, 160); // fits beside the signal bars on a 1280x800 laptop
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    const PositionScatter *s_;
};

// Texts through DeviationView::tr: the canvas is a plain QWidget, whose tr() would look them up
// under "QWidget", not where lupdate files them.
void DeviationView::Canvas::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    const QColor text = pal.color(QPalette::Text);
    QColor grid = pal.color(QPalette::Mid);
    p.fillRect(rect(), pal.color(QPalette::Base));

    const QFontMetrics fm(font());
    const int left = fm.horizontalAdvance(QStringLiteral("-000.000")) + fm.height() + 8;
    const int bottom = fm.height() * 2 + 6;
    const int side = std::max(50, std::min(width() - left - 12, height() - bottom - 12));
    const QRect plot(left + (width() - left - 12 - side) / 2, 8, side, side);

    const auto &pts = s_->points();
    const auto &st = s_->stats();
    if (pts.empty()) {
        p.setPen(text);
        p.drawRect(plot);
        p.drawText(plot, Qt::AlignCenter, DeviationView::tr("No position yet"));
        return;
    }

    // Half range: every point and every circle fits, with a margin, on 1-2-5 steps.
    double extent = std::max({st.cep95, st.drms2, 0.005});
    for (const auto &pt : pts) extent = std::max({extent, std::fabs(pt.east), std::fabs(pt.north)});
    // Steps of 1-2-5 in the unit shown (feet when imperial), the plot itself in metres.
    const double k = fmt::lengthFactor(units);
    const double step = niceCeil(extent * k * 1.1 / 4.0) / k;
    const double half = step * std::ceil(extent * 1.1 / step);
    const double scale = plot.width() / (2.0 * half); // px per metre
    const QPointF c = QRectF(plot).center();
    auto map = [&](double e, double n) { return QPointF(c.x() + e * scale, c.y() - n * scale); };

    // Grid and tick labels.
    p.setClipRect(plot.adjusted(-1, -1, 1, 1));
    QPen gp(grid, 0, Qt::DotLine);
    p.setPen(gp);
    const int ticks = static_cast<int>(std::round(half / step));
    for (int i = -ticks; i <= ticks; ++i) {
        const double v = i * step;
        p.drawLine(map(v, -half), map(v, half));
        p.drawLine(map(-half, v), map(half, v));
    }
    p.setPen(QPen(grid, 1));
    p.drawLine(map(0, -half), map(0, half));
    p.drawLine(map(-half, 0), map(half, 0));
    p.setClipping(false);
    p.setPen(QPen(text, 1));
    p.drawRect(plot);
    for (int i = -ticks; i <= ticks; i += std::max(1, ticks / 2)) {
        const double v = i * step;
        const QString t = QString::number(v * k, 'g', 6);
        const QPointF xb = map(v, -half);
        p.drawText(QRectF(xb.x() - 40, plot.bottom() + 2, 80, fm.height()), Qt::AlignHCenter, t);
        const QPointF yl = map(-half, v);
        p.drawText(QRectF(0, yl.y() - fm.height() / 2.0, plot.left() - 4, fm.height()),
                   Qt::AlignRight | Qt::AlignVCenter, t);
    }
    p.drawText(QRectF(plot.left(), plot.bottom() + 2 + fm.height(), plot.width(), fm.height()),
               Qt::AlignHCenter, DeviationView::tr("East (%1)").arg(fmt::lengthUnit(units)));
    p.save();
    p.translate(2, plot.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-plot.height() / 2.0, 0, plot.height(), fm.height()), Qt::AlignHCenter,
               DeviationView::tr("North (%1)").arg(fmt::lengthUnit(units)));
    p.restore();

    // Points, oldest first so the newest are on top.
    p.setClipRect(plot);
    const double r = std::clamp(side / 160.0, 2.0, 4.0);
    std::set<int> fixes;
    // Thousands of points: one drawPoints call per run of one fix type, as round dots of the
    // pen's width, without antialiasing (a sixth of the cost of one antialiased ellipse each).
    p.setRenderHint(QPainter::Antialiasing, false);
    QVector<QPointF> run;
    auto flush = [&](FixType fix) {
        if (run.isEmpty()) return;
        p.setPen(QPen(style::fixTypeColor(fix), 2 * r, Qt::SolidLine, Qt::RoundCap));
        p.drawPoints(run.constData(), int(run.size()));
        run.clear();
    };
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (i > 0 && pts[i].fix != pts[i - 1].fix) flush(pts[i - 1].fix);
        run.push_back(map(pts[i].east, pts[i].north));
        fixes.insert(static_cast<int>(pts[i].fix));
    }
    flush(pts.back().fix);
    p.setRenderHint(QPainter::Antialiasing, true);
    const auto &last = pts.back();
    p.setBrush(style::fixTypeColor(last.fix));
    p.setPen(QPen(text, 1.5));
    p.drawEllipse(map(last.east, last.north), r * 1.8, r * 1.8);

    // The circles about the centre, told apart by line style as well as by label.
    struct Circle {
        double radius;
        Qt::PenStyle style;
        QString name;
    };
    const Circle circles[] = {{st.cep50, Qt::DashLine, DeviationView::tr("CEP50")},
                              {st.cep95, Qt::SolidLine, DeviationView::tr("CEP95")},
                              {st.drms2, Qt::DotLine, DeviationView::tr("2DRMS")}};
    p.setBrush(Qt::NoBrush);
    for (const Circle &ci : circles) {
        if (ci.radius <= 0) continue;
        p.setPen(QPen(text, 1.4, ci.style));
        const double rp = ci.radius * scale;
        p.drawEllipse(c, rp, rp);
        const QPointF at = c + QPointF(rp * 0.7071, -rp * 0.7071);
        // On a translucent plate so the name reads over a dense cloud.
        const QRectF plateRect(at + QPointF(3, -3 - fm.ascent()),
                               QSizeF(fm.horizontalAdvance(ci.name) + 4, fm.height()));
        QColor plate = pal.color(QPalette::Base);
        plate.setAlpha(190);
        p.fillRect(plateRect, plate);
        p.drawText(plateRect, Qt::AlignCenter, ci.name);
    }
    // Mean offset from a typed reference.
    if (s_->hasReference()) {
        const QPointF m = map(st.meanEast, st.meanNorth);
        p.setPen(QPen(text, 2));
        p.drawLine(m + QPointF(-6, 0), m + QPointF(6, 0));
        p.drawLine(m + QPointF(0, -6), m + QPointF(0, 6));
    }
    p.setClipping(false);

    // Legend of the fix types shown (top left inside the plot).
    int y = plot.top() + 6;
    for (int f : fixes) {
        const QString name = style::fixTypeLabel(static_cast<FixType>(f));
        const QRect box(plot.left() + 6, y, fm.horizontalAdvance(name) + 22, fm.height() + 2);
        QColor bg = pal.color(QPalette::Base);
        bg.setAlpha(210);
        p.fillRect(box, bg);
        p.setPen(Qt::NoPen);
        p.setBrush(style::fixTypeColor(static_cast<FixType>(f)));
        p.drawEllipse(QPointF(box.left() + 8, box.center().y() + 1), 4, 4);
        p.setPen(text);
        p.drawText(box.adjusted(18, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, name);
        y += fm.height() + 2;
    }

    // Scale bar (bottom right inside the plot): one grid step.
    const double barPx = step * scale;
    const QPointF b1(plot.right() - 10 - barPx, plot.bottom() - 10);
    const QPointF b2(plot.right() - 10, plot.bottom() - 10);
    // As short as the step allows ("0.05 m", "2 m", "500 m").
    const QString bt = QString::number(step * k, 'g', 6) + ' ' + fmt::lengthUnit(units);
    const QRectF bbox(b1.x() - 4, b1.y() - fm.height() - 6, barPx + 8, fm.height() + 10);
    QColor bg = pal.color(QPalette::Base);
    bg.setAlpha(210);
    p.fillRect(bbox.adjusted(std::min(0.0, barPx - fm.horizontalAdvance(bt) - 8), 0, 0, 0), bg);
    p.setPen(QPen(text, 2));
    p.drawLine(b1, b2);
    p.drawLine(b1 + QPointF(0, -4), b1 + QPointF(0, 4));
    p.drawLine(b2 + QPointF(0, -4), b2 + QPointF(0, 4));
    p.drawText(QRectF(b2.x() - std::max(barPx, double(fm.horizontalAdvance(bt))),
                      b1.y() - fm.height() - 3, std::max(barPx, double(fm.horizontalAdvance(bt))),
                      fm.height()),
               Qt::AlignRight | Qt::AlignBottom, bt);
}

DeviationView::DeviationView(ReceiverStateModel *model, QWidget *parent)
    : QWidget(parent), model_(model), timer_(new QTimer(this)) {
    auto *outer = new QVBoxLayout(this);

    auto *controls = new QHBoxLayout;
    useRef_ = new QCheckBox(tr("Reference"));
    useRef_->setObjectName("deviationUseReference");
    useRef_->setToolTip(tr("Centre on a known position instead of the mean of the positions"));
    refLat_ = new QLineEdit;
    refLat_->setObjectName("deviationRefLat");
    refLat_->setPlaceholderText(tr("latitude, e.g. 55.7512 N"));
    refLon_ = new QLineEdit;
    refLon_->setObjectName("deviationRefLon");
    refLon_->setPlaceholderText(tr("longitude, e.g. 37.6181 E"));
    capacity_ = new QSpinBox;
    capacity_->setObjectName("deviationCapacity");
    capacity_->setRange(10, 1000000);
    capacity_->setValue(3600);
    capacity_->setToolTip(tr("How many of the latest positions are kept"));
    reset_ = new QPushButton(tr("Reset"));
    reset_->setObjectName("deviationReset");
    controls->addWidget(useRef_);
    controls->addWidget(refLat_, 1);
    controls->addWidget(refLon_, 1);
    controls->addSpacing(8);
    controls->addWidget(new QLabel(tr("Points")));
    controls->addWidget(capacity_);
    controls->addWidget(reset_);
    outer->addLayout(controls);
    refStatus_ = new QLabel;
    refStatus_->setObjectName("deviationRefStatus");
    refStatus_->hide();
    outer->addWidget(refStatus_);

    auto *fig = new QGridLayout;
    auto add = [&](int col, const QString &name, const char *obj) {
        fig->addWidget(new QLabel(name + QLatin1Char(':')), 0, col * 2);
        auto *v = new QLabel(fmt::dash());
        v->setObjectName(QString::fromLatin1(obj));
        v->setTextInteractionFlags(Qt::TextSelectableByMouse);
        QFont f = v->font();
        f.setBold(true);
        v->setFont(f);
        fig->addWidget(v, 0, col * 2 + 1);
        return v;
    };
    cep50_ = add(0, tr("CEP50"), "deviationCep50");
    cep95_ = add(1, tr("CEP95"), "deviationCep95");
    drms2_ = add(2, tr("2DRMS"), "deviation2drms");
    count_ = add(3, tr("Points"), "deviationCount");
    fig->addWidget(new QLabel(tr("Centre:")), 1, 0);
    centre_ = new QLabel(fmt::dash());
    centre_->setObjectName("deviationCentre");
    centre_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    fig->addWidget(centre_, 1, 1, 1, 3);
    fig->addWidget(new QLabel(tr("Mean offset:")), 1, 4);
    offset_ = new QLabel(fmt::dash());
    offset_->setObjectName("deviationMeanOffset");
    fig->addWidget(offset_, 1, 5, 1, 3);
    for (int c = 1; c < 8; c += 2) fig->setColumnStretch(c, 1);
    outer->addLayout(fig);

    canvas_ = new Canvas(&scatter_, this);
    outer->addWidget(canvas_, 1);

    connect(reset_, &QPushButton::clicked, this, &DeviationView::reset);
    connect(capacity_, &QSpinBox::valueChanged, this, [this](int n) {
        scatter_.setCapacity(static_cast<std::size_t>(n));
        dirty_ = true;
    });
    connect(useRef_, &QCheckBox::toggled, this, &DeviationView::applyReference);
    connect(refLat_, &QLineEdit::editingFinished, this, &DeviationView::applyReference);
    connect(refLon_, &QLineEdit::editingFinished, this, &DeviationView::applyReference);
    connect(model_, &ReceiverStateModel::updated, this, &DeviationView::takeEpoch);
    startRefreshTimer(*timer_, kStatisticsRefreshMs, this, [this] {
        if (dirty_) refresh();
    });
    refresh();
}

int DeviationView::capacity() const {
    return capacity_->value();
}

void DeviationView::setCapacity(int n) {
    capacity_->setValue(n);
}

void DeviationView::takeEpoch() {
    if (model_->epochCount() == 0) {
        reset();
        return;
    }
    const Epoch &e = model_->state().epoch;
    if (!e.lat || !e.lon || e.fix == FixType::None) return;
    scatter_.add(*e.lat, *e.lon, e.fix);
    dirty_ = true;
}

void DeviationView::reset() {
    scatter_.clear();
    dirty_ = true;
    refresh();
}

std::optional<double> DeviationView::parseDegrees(const QString &textIn, bool latitude) {
    QString t = textIn.trimmed().toUpper();
    t.remove(QChar(0x00B0));
    if (t.isEmpty()) return std::nullopt;
    double sign = 1.0;
    const QChar last = t.back();
    const QString pos = latitude ? QStringLiteral("N") : QStringLiteral("E");
    const QString neg = latitude ? QStringLiteral("S") : QStringLiteral("W");
    if (last.isLetter()) {
        if (QString(last) == neg)
            sign = -1.0;
        else if (QString(last) != pos)
            return std::nullopt;
        t.chop(1);
    }
    bool ok = false;
    const double v = t.trimmed().replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok) * sign;
    if (!ok || !std::isfinite(v) || std::fabs(v) > (latitude ? 90.0 : 180.0)) return std::nullopt;
    return v;
}

bool DeviationView::setReference(const QString &lat, const QString &lon) {
    refLat_->setText(lat);
    refLon_->setText(lon);
    const QSignalBlocker b(useRef_);
    useRef_->setChecked(!lat.trimmed().isEmpty() || !lon.trimmed().isEmpty());
    applyReference();
    return !useRef_->isChecked() || scatter_.hasReference();
}

void DeviationView::applyReference() {
    if (!useRef_->isChecked()) {
        scatter_.setReference(std::nullopt, std::nullopt);
        refStatus_->hide();
    } else {
        const auto lat = parseDegrees(refLat_->text(), true);
        const auto lon = parseDegrees(refLon_->text(), false);
        scatter_.setReference(lat && lon ? lat : std::nullopt, lat && lon ? lon : std::nullopt);
        if (lat && lon) {
            refStatus_->hide();
        } else {
            refStatus_->setText(
                    tr("Reference not used: type degrees such as 55.75123456 N and "
                       "37.61812345 E (or signed, -33.9 for south). Centred on the mean."));
            refStatus_->show();
        }
    }
    dirty_ = true;
    refresh();
}

void DeviationView::setDisplayPrefs(const DisplayPrefs &prefs) {
    prefs_ = prefs;
    canvas_->units = prefs.units;
    refresh();
}

void DeviationView::refresh() {
    dirty_ = false;
    const auto &st = scatter_.stats();
    count_->setText(QString::number(st.count));
    if (st.count == 0) {
        for (QLabel *l : {cep50_, cep95_, drms2_, offset_, centre_}) l->setText(fmt::dash());
    } else {
        const UnitSystem u = prefs_.units;
        cep50_->setText(metres(st.cep50, u));
        cep95_->setText(metres(st.cep95, u));
        drms2_->setText(metres(st.drms2, u));
        centre_->setText((scatter_.hasReference() ? tr("reference %1, %2") : tr("mean %1, %2"))
                                 .arg(fmt::latitude(st.centreLat, prefs_.coordinates),
                                      fmt::longitude(st.centreLon, prefs_.coordinates)));
        offset_->setText(scatter_.hasReference()
                                 ? tr("%1 east, %2 north")
                                           .arg(metres(st.meanEast, u), metres(st.meanNorth, u))
                                 : fmt::dash());
    }
    canvas_->update();
}

} // namespace gnss::ui
