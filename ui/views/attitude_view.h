#pragma once
// AttitudeView: roll/pitch/yaw and accelerations (NVS PNVGIMU and the like, through
// ReceiverState::attitude) and a table of time-mark events, newest first. Refreshes on a 10 Hz
// timer when a new epoch has arrived; the table is rebuilt only when the events changed.
#include "models/value_format.h"

#include <QWidget>

#include <cstdint>
#include <optional>

class QLabel;
class QTableWidget;
class QTimer;

namespace gnss::ui {

class ReceiverStateModel;

class AttitudeView : public QWidget {
    Q_OBJECT
public:
    explicit AttitudeView(ReceiverStateModel *model, QWidget *parent = nullptr);

    enum Column { Counter, Tow, Utc, Latitude, Longitude, Altitude, ColumnCount };
    // Most events listed (the state keeps more).
    static constexpr int kMaxRows = 500;

    // Times in the user's zone, coordinates in their format, altitudes in their unit.
    void setDisplayPrefs(const DisplayPrefs &prefs);

public slots:
    void refresh();

private:
    void setHeaders();
    DisplayPrefs prefs_;
    void poll();

    ReceiverStateModel *model_;
    QTimer *timer_;
    quint64 shownEpochs_ = ~quint64(0);
    std::size_t shownMarks_ = ~std::size_t(0);
    std::optional<std::int64_t> shownCounter_;
    std::optional<double> shownTow_;
    QLabel *time_, *roll_, *pitch_, *yaw_, *accNorth_, *accEast_, *accDown_, *markCount_;
    QTableWidget *marks_;
};

} // namespace gnss::ui
