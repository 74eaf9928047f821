#pragma once
// The whole-log views with their few controls: LogChartsPanel (which quantity to plot, a button
// to show the whole log again) and LogTrackPanel (the reference point, a button to fit).
#include "logview/log_plot.h"
#include "logview/log_track.h"

#include <QWidget>

class QComboBox;
class QLineEdit;
class QLabel;

namespace gnss::ui {

class LogChartsPanel : public QWidget {
    Q_OBJECT
public:
    explicit LogChartsPanel(LogCursor *cursor, QWidget *parent = nullptr);
    LogPlot *plot() const { return plot_; }
    QComboBox *quantityBox() const { return quantity_; }

private:
    LogPlot *plot_;
    QComboBox *quantity_;
};

class LogTrackPanel : public QWidget {
    Q_OBJECT
public:
    explicit LogTrackPanel(LogCursor *cursor, QWidget *parent = nullptr);
    LogTrack *track() const { return track_; }
    // "55.75, 37.62" (degrees, latitude first) or empty for the mean; false and a word when the
    // text is no position.
    bool setReferenceText(const QString &text);

private:
    LogTrack *track_;
    QLineEdit *reference_;
    QLabel *message_;
};

} // namespace gnss::ui
