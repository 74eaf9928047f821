#pragma once
// A Qt Chart that follows the palette (light or dark) instead of Qt Charts' fixed white theme:
// background, title, legend, axis labels and grid from the widget's palette.
#include <QList>

class QAbstractAxis;
class QChart;
class QChartView;
class QPalette;

namespace gnss::style {

void applyChartPalette(QChart *chart, QChartView *view, const QList<QAbstractAxis *> &axes,
                       const QPalette &palette);

} // namespace gnss::style
