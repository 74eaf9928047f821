#pragma once
// The qualification's plots, painted with QPainter into any area: the Qualification dock and the
// log viewer paint them live, the report into images. Colours come from the caller (the palette).
#include <QColor>
#include <QString>

#include <cstdint>
#include <vector>

class QPainter;
class QRectF;

namespace gnss {
enum class ReceiverAction : std::uint8_t;
}

namespace gnss::qualify {

struct ReportReceiver;

// A kind of start in the user's language ("cold", "warm", "hot"), as the plots and the report
// name it.
QString startName(ReceiverAction a);

// The CDF of the times to first fix: one step line per series (a receiver's kind of start),
// seconds along, share of runs (0..100 %) up; axes, grid and a legend in `area` (its box
// filled with the painter's background()).
struct CdfSeries {
    QString label; // "cold", or "#2 cold" with several receivers
    QColor colour;
    std::vector<double> seconds; // of the fixed runs
};
std::vector<CdfSeries> cdfSeriesOf(const std::vector<ReportReceiver> &receivers);
void paintCdf(QPainter &p, const QRectF &area, const std::vector<CdfSeries> &series,
              const QColor &text, const QColor &grid);

// A histogram of horizontal errors: `values` in metres shown in `unitSymbol` (`perMetre` units a
// metre), about 20 bins from 0 to the 99th percentile (the rest in the last bin), the share of
// epochs up; CEP50/CEP95 marked when given (metres).
void paintHistogram(QPainter &p, const QRectF &area, const std::vector<double> &values,
                    const QString &unitSymbol, double perMetre, const QColor &bars,
                    const QColor &text, const QColor &grid, double cep50 = 0, double cep95 = 0);

// Errors over time: the horizontal and the vertical distance from the reference (metres, in the
// order of the epochs; a vertical NaN where there is no height), shown in `unitSymbol`
// (`perMetre` of them a metre) against the epoch's number; a long series is drawn as the largest
// error of each pixel's epochs.
void paintErrorSeries(QPainter &p, const QRectF &area, const std::vector<double> &horizontal,
                      const std::vector<double> &vertical, const QString &unitSymbol,
                      double perMetre, const QColor &horizontalColour, const QColor &verticalColour,
                      const QColor &text, const QColor &grid);

} // namespace gnss::qualify
