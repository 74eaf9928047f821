#pragma once
// ChartsView: time series the user picks (satellites used, HDOP/PDOP, fix type, mean SNR per
// constellation, standard deviations, baseline length, altitude, speed) over a rolling window.
// Series sharing a unit share one chart; charts stack vertically. Data comes from a
// TimeSeriesModel fed per epoch; the charts redraw on a 2 Hz timer, never per epoch.
#include "models/time_series_model.h"

#include <QWidget>

#include <array>

class QListWidget;
class QSpinBox;
class QTimer;
class QVBoxLayout;
class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;
class QAbstractAxis;

namespace gnss::ui {

class ReceiverStateModel;

class ChartsView : public QWidget {
    Q_OBJECT
public:
    explicit ChartsView(ReceiverStateModel *model, QWidget *parent = nullptr);

    TimeSeriesModel *seriesModel() const { return series_; }

    // The picked series by stable key (TimeSeriesModel::key), for QSettings.
    QStringList checkedSeries() const;
    void setCheckedSeries(const QStringList &keys);
    // Rolling window in minutes (default 10).
    int windowMinutes() const;
    void setWindowMinutes(int minutes);
    // Lengths and speeds in the user's units (titles and values).
    void setDisplayPrefs(const DisplayPrefs &prefs);

    // The line of a series (nullptr while it is not picked); tests read its points.
    QLineSeries *lineSeries(TimeSeriesModel::Series s) const { return lines_[s]; }
    // The chart of a group (nullptr while none of its series is picked).
    QChartView *chartView(TimeSeriesModel::Group g) const { return groups_[g].view; }

    // Most points drawn per line: longer series are reduced to each bucket's min and max.
    static constexpr int kMaxPointsPerLine = 2000;

public slots:
    // Redraws now if the data or the selection changed (the timer calls this at 2 Hz).
    void redraw();

protected:
    void changeEvent(QEvent *e) override;

private:
    UnitSystem units_ = UnitSystem::Metric;
    struct GroupChart {
        QChartView *view = nullptr;
        QChart *chart = nullptr;
        QValueAxis *x = nullptr;
        QAbstractAxis *y = nullptr;
        int fixLo = -1, fixHi = -1; // fix types named on the fix chart's axis
    };
    void rebuildCharts();
    GroupChart &ensureGroup(TimeSeriesModel::Group g);
    void applyTheme();

    TimeSeriesModel *series_;
    QTimer *timer_;
    QListWidget *list_;
    QSpinBox *window_;
    QVBoxLayout *chartsLayout_;
    std::array<GroupChart, TimeSeriesModel::GroupCount> groups_{};
    std::array<QLineSeries *, TimeSeriesModel::SeriesCount> lines_{};
    quint64 drawnRevision_ = ~quint64(0);
    bool selectionChanged_ = true;
};

} // namespace gnss::ui
