#pragma once
// The qualification's plots as widgets: the CDF of the times to first fix and the histogram of
// horizontal errors, painted by protocol/qualify/plots (the report paints the same) in the
// widget's palette.
#include "qualify/plots.h"

#include <QWidget>

#include <vector>

namespace gnss::ui {

class CdfPlot : public QWidget {
    Q_OBJECT
public:
    explicit CdfPlot(QWidget *parent = nullptr);
    void setSeries(std::vector<qualify::CdfSeries> series);
    const std::vector<qualify::CdfSeries> &series() const { return series_; }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    std::vector<qualify::CdfSeries> series_;
};

class ErrorHistogram : public QWidget {
    Q_OBJECT
public:
    explicit ErrorHistogram(QWidget *parent = nullptr);
    // Horizontal errors in metres, shown in `unit` (`perMetre` of them a metre); CEP50/95 marked.
    void setValues(std::vector<double> metres, const QString &unit, double perMetre, double cep50,
                   double cep95);
    std::size_t count() const { return values_.size(); }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    std::vector<double> values_;
    QString unit_ = QStringLiteral("m");
    double perMetre_ = 1, cep50_ = 0, cep95_ = 0;
};

class ErrorSeriesPlot : public QWidget {
    Q_OBJECT
public:
    explicit ErrorSeriesPlot(QWidget *parent = nullptr);
    // Horizontal and vertical errors in metres, in epoch order (vertical NaN: no height).
    void setValues(std::vector<double> horizontal, std::vector<double> vertical,
                   const QString &unit, double perMetre);
    std::size_t count() const { return horizontal_.size(); }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    std::vector<double> horizontal_, vertical_;
    QString unit_ = QStringLiteral("m");
    double perMetre_ = 1;
};

} // namespace gnss::ui
