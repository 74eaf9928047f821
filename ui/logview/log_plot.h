#pragma once
// LogPlot: one quantity of every epoch of the log (altitude, speed, satellites used, HDOP, mean
// SNR) against the epochs, decimated per pixel column (its minimum to maximum, coloured by the
// column's fix type), so a day at 10 Hz draws as fast as a minute. Wheel zooms about the mouse,
// dragging pans, a click moves the cursor, a double click shows the whole log again.
#include "logview/drag_gesture.h"
#include "logview/log_cursor.h"
#include "models/value_format.h"

#include <QImage>
#include <QWidget>

namespace gnss::ui {

class LogPlot : public QWidget {
    Q_OBJECT
public:
    enum class Quantity { Altitude, Speed, Satellites, Hdop, Snr };

    explicit LogPlot(LogCursor *cursor, QWidget *parent = nullptr);

    void setQuantity(Quantity q);
    Quantity quantity() const { return quantity_; }
    void setDisplayPrefs(const DisplayPrefs &prefs);
    // The epochs shown, [first, last] (fractional while zoomed in).
    std::pair<double, double> window() const { return {first_, last_}; }
    void setWindow(double first, double last);
    void showAll();
    // The value and its unit's name, as plotted (NaN when the epoch has none).
    double value(const logview::EpochRecord &r) const;
    QString unit() const;
    static QString quantityName(Quantity q);

    QRect plotRect() const;
    double epochAtX(double x) const;
    double xOfEpoch(double epoch) const;

    QSize sizeHint() const override { return {600, 220}; }
    QSize minimumSizeHint() const override { return {200, 60}; }

protected:
    void paintEvent(QPaintEvent *) override;
    void wheelEvent(QWheelEvent *e) override;
    void mousePressEvent(QMouseEvent *e) override;
    void mouseMoveEvent(QMouseEvent *e) override;
    void mouseReleaseEvent(QMouseEvent *e) override;
    void mouseDoubleClickEvent(QMouseEvent *e) override;

    void changeEvent(QEvent *e) override;

private:
    void keepCursorInView(std::size_t epoch);
    void invalidate();
    void renderSeries(QPainter &p);

    LogCursor *cursor_;
    Quantity quantity_ = Quantity::Altitude;
    DisplayPrefs prefs_;
    double first_ = 0, last_ = 0;
    bool zoomed_ = false;
    DragGesture press_;
    double pressFirst_ = 0, pressLast_ = 0; // the window when it began
    QImage image_; // the series, axes and labels (the cursor is drawn over it)
    bool imageValid_ = false;
};

} // namespace gnss::ui
