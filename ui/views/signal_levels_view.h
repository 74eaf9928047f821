#pragma once
// SignalLevelsView: one SNR bar per satellite and signal, grouped by constellation and signal,
// used satellites filled, tracked ones outlined, ids below. Ids stay legible at any width:
// level while they fit their slot, turned on end when they do not, and when even that is too
// crowded only every n-th id of a group is written. Repaints on a timer, from the model.
#include "core/satellite.h"

#include <QFontMetricsF>
#include <QTimer>
#include <QWidget>

namespace gnss::ui {

class SatelliteModel;

class SignalLevelsView : public QWidget {
    Q_OBJECT
public:
    explicit SignalLevelsView(SatelliteModel *model, QWidget *parent = nullptr);

    struct Bar {
        int row;       // model row
        QRectF rect;   // the bar at its full SNR height
        QString label; // "G05", "G05 L5"
        QString id;    // written below the bar ("G05"); empty when thinned out
        QRectF idRect; // where the id is written (turned on end when `rotated`)
    };
    struct Layout {
        QRectF area; // the plot
        QVector<Bar> bars;
        QFont idFont;
        bool rotated = false; // ids turned on end
        int every = 1;        // one id in `every` is written
        double slot = 0;      // the width each bar stands in
    };
    // What the next paint draws (for tests).
    Layout layout() const;
    QVector<Bar> layoutBars() const { return layout().bars; }
    // The caption under a group of bars, shortened to fit `width` ("GLONASS L2OF", "R L2OF",
    // "L2OF", "R"; elided only when even the letter does not fit).
    static QString groupCaption(const QFontMetricsF &fm, Constellation system, int signalId,
                                double width);

    QSize sizeHint() const override { return {600, 220}; }
    QSize minimumSizeHint() const override { return {200, 100}; }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    SatelliteModel *model_;
    QTimer repaintTimer_;
    bool dirty_ = true;
};

} // namespace gnss::ui
