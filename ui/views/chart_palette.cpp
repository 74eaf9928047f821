#include "views/chart_palette.h"

#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include <QLegend>
#include <QPalette>

namespace gnss::style {

void applyChartPalette(QChart *chart, QChartView *view, const QList<QAbstractAxis *> &axes,
                       const QPalette &p) {
    const QColor text = p.color(QPalette::WindowText), base = p.color(QPalette::Base);
    const QColor grid = p.color(QPalette::Mid);
    chart->setBackgroundBrush(base);
    chart->setTitleBrush(text);
    chart->legend()->setLabelColor(text);
    if (view) view->setBackgroundBrush(p.color(QPalette::Window));
    for (QAbstractAxis *a : axes) {
        a->setLabelsBrush(text);
        a->setTitleBrush(text);
        a->setGridLineColor(grid);
        a->setLinePenColor(grid);
    }
}

} // namespace gnss::style
