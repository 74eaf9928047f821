// The CDF and histogram widgets: protocol/qualify/plots painted in the palette's colours.
#include "qualify/qualify_plots.h"

#include <QPainter>

namespace gnss::ui {

namespace {

QColor gridColour(const QPalette &p) {
    QColor c = p.color(QPalette::WindowText);
    c.setAlphaF(0.18f);
    return c;
}

} // namespace

CdfPlot::CdfPlot(QWidget *parent) : QWidget(parent) {
    setMinimumSize(160, 40);
}

void CdfPlot::setSeries(std::vector<qualify::CdfSeries> series) {
    series_ = std::move(series);
    update();
}

void CdfPlot::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    qualify::paintCdf(p, QRectF(rect()), series_, palette().color(QPalette::WindowText),
                      gridColour(palette()));
}

ErrorHistogram::ErrorHistogram(QWidget *parent) : QWidget(parent) {
    setMinimumSize(160, 40);
}

void ErrorHistogram::setValues(std::vector<double> metres, const QString &unit, double perMetre,
                               double cep50, double cep95) {
    values_ = std::move(metres);
    unit_ = unit;
    perMetre_ = perMetre;
    cep50_ = cep50;
    cep95_ = cep95;
    update();
}

void ErrorHistogram::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    qualify::paintHistogram(
            p, QRectF(rect()), values_, unit_, perMetre_, palette().color(QPalette::Highlight),
            palette().color(QPalette::WindowText), gridColour(palette()), cep50_, cep95_);
}

ErrorSeriesPlot::ErrorSeriesPlot(QWidget *parent) : QWidget(parent) {
    setMinimumSize(160, 40);
}

void ErrorSeriesPlot::setValues(std::vector<double> horizontal, std::vector<double> vertical,
                                const QString &unit, double perMetre) {
    horizontal_ = std::move(horizontal);
    vertical_ = std::move(vertical);
    unit_ = unit;
    perMetre_ = perMetre;
    update();
}

void ErrorSeriesPlot::paintEvent(QPaintEvent *) {
    QPainter p(this);
    qualify::paintErrorSeries(p, QRectF(rect()), horizontal_, vertical_, unit_, perMetre_,
                              palette().color(QPalette::Highlight), QColor(0xff, 0x7f, 0x0e),
                              palette().color(QPalette::WindowText), gridColour(palette()));
}

} // namespace gnss::ui
