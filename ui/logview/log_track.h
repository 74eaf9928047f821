#pragma once
// LogTrack: where the receiver was over the whole log, east and north metres about the mean
// position (or a reference the user types), each epoch a dot in its fix type's colour, the
// cursor's epoch ringed. Wheel zooms about the mouse, dragging pans, a click moves the cursor to
// the nearest epoch, a double click fits the whole track. The dots are drawn once into an image
// and only redrawn when the view or the log changes, so the cursor moves cheaply.
#include "logview/drag_gesture.h"
#include "logview/log_cursor.h"
#include "models/value_format.h"

#include <QImage>
#include <QWidget>
#include <optional>
#include <vector>

namespace gnss::ui {

class LogTrack : public QWidget {
    Q_OBJECT
public:
    explicit LogTrack(LogCursor *cursor, QWidget *parent = nullptr);

    // The origin of east/north: a point (degrees), or the mean of the log's positions.
    void setReference(std::optional<std::pair<double, double>> latLon);
    std::pair<double, double> origin() const { return origin_; }
    void setDisplayPrefs(const DisplayPrefs &prefs);
    void fit();

    // East/north (metres) of epoch k, when it has a position.
    std::optional<QPointF> enOf(std::size_t k) const;
    QPointF toPixel(QPointF en) const;
    // The nearest positioned epoch within `radius` pixels of a point, if any.
    std::optional<std::size_t> epochNear(QPointF pixel, double radius) const;
    double pixelsPerMetre() const { return scale_; }

    QSize sizeHint() const override { return {360, 360}; }
    QSize minimumSizeHint() const override { return {140, 100}; }

protected:
    void paintEvent(QPaintEvent *) override;
    void resizeEvent(QResizeEvent *) override;
    void wheelEvent(QWheelEvent *e) override;
    void mousePressEvent(QMouseEvent *e) override;
    void mouseMoveEvent(QMouseEvent *e) override;
    void mouseReleaseEvent(QMouseEvent *e) override;
    void mouseDoubleClickEvent(QMouseEvent *e) override;

private:
    void reload();
    void renderDots();
    QPointF toMetres(QPointF pixel) const;

    LogCursor *cursor_;
    std::optional<std::pair<double, double>> reference_;
    std::pair<double, double> origin_{0, 0};
    DisplayPrefs prefs_;
    std::vector<QPointF> en_; // per epoch (NaN: no position)
    std::vector<quint8> fix_; // per epoch
    QPointF centre_;          // metres at the widget's centre
    double scale_ = 1;        // pixels per metre
    bool userView_ = false;   // zoomed or panned: a growing log does not refit
    QImage dots_;
    bool dotsValid_ = false;
    DragGesture press_;
    QPointF pressCentre_; // the centre when it began
};

} // namespace gnss::ui
