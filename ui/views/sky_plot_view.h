#pragma once
// SkyPlotView: satellites on a polar plot (azimuth clockwise from north, elevation rings),
// one colour and marker shape per constellation (ui/style), used satellites filled, tracked ones
// outlined, ones without signal dashed and dimmed; labels, SNR, optional tracks, a constellation
// filter, the elevation mask, and a tooltip per satellite. Repaints on a timer, from the model.
#include "core/satellite.h"

#include <QSet>
#include <QTimer>
#include <QWidget>

class QPainter;

namespace gnss::ui {

class SatelliteModel;
struct SatelliteRow;

class SkyPlotView : public QWidget {
    Q_OBJECT
public:
    explicit SkyPlotView(SatelliteModel *model, QWidget *parent = nullptr);

    void setShowTracks(bool on);
    bool showTracks() const { return showTracks_; }
    void setShowLabels(bool on);
    bool showLabels() const { return showLabels_; }
    void setElevationMask(double degrees); // < 0: none drawn
    double elevationMask() const { return mask_; }
    void setConstellationVisible(Constellation c, bool visible);
    bool constellationVisible(Constellation c) const { return !hidden_.contains(int(c)); }

    // One drawn satellite (all signals of a satellite share a marker).
    struct Marker {
        SatelliteRef sat;
        QPointF pos;
        int snr = -1; // best signal, -1 when none
        bool used = false;
        QString label;
        QString tooltip;
        QString text;        // the label as drawn ("G05 42"); empty when it had no room
        QRectF labelRect;    // where it is drawn; null when dropped
        bool leader = false; // drawn away from its marker, with a line to it
    };
    // What the next paint draws (for tests and the tooltip), labels placed so that none
    // overlaps another label or a marker: a label with no free place is dropped (the marker
    // keeps its tooltip).
    QVector<Marker> markers() const;
    // The compass letters and the elevation rings' degrees, where paint draws them (labels keep
    // off them too).
    struct GridText {
        QString text;
        QRectF rect;
        bool ring = false; // a ring's degrees (drawn in the grid's colour), else a letter
    };
    QVector<GridText> gridTexts() const;

    QSize sizeHint() const override { return {420, 420}; }
    QSize minimumSizeHint() const override { return {160, 160}; }

protected:
    void paintEvent(QPaintEvent *) override;
    bool event(QEvent *e) override;
    void contextMenuEvent(QContextMenuEvent *e) override;

private:
    QPointF project(double azimuth, double elevation) const;
    double markerSize() const;
    QFont labelFont() const;
    void placeLabels(QVector<Marker> &markers) const;
    double radius() const;
    QPointF center() const;

    SatelliteModel *model_;
    QTimer repaintTimer_;
    bool dirty_ = true;
    bool showTracks_ = false;
    bool showLabels_ = true;
    double mask_ = -1;
    QSet<int> hidden_;
};

// Draws a constellation's marker shape centred at p (shared with the signal view's legend).
void drawConstellationMarker(QPainter &p, Constellation c, QPointF center, double size);

} // namespace gnss::ui
