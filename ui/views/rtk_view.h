#pragma once
// RtkView: the RTK panel (issue 8): mode, base-station statistics and distance, base-to-rover
// baseline, heading and antenna baseline, standard deviations, receiver DOPs, and a correction
// age watchdog that turns red past a threshold. Reads ReceiverState::rtk through the model,
// refreshes on a 10 Hz timer when a new epoch has arrived, never per update.
#include "models/value_format.h"

#include <QWidget>

#include <optional>
#include <vector>

class QDoubleSpinBox;
class QLabel;
class QStackedWidget;
class QTimer;

namespace gnss {
struct RtkState;
}

namespace gnss::ui {

class ReceiverStateModel;

class RtkView : public QWidget {
    Q_OBJECT
public:
    explicit RtkView(ReceiverStateModel *model, QWidget *parent = nullptr);

    // Correction age (seconds) above which the watchdog turns red; default 10 s.
    double correctionAgeThreshold() const;
    void setCorrectionAgeThreshold(double seconds);
    // Lengths and speeds in the user's units.
    void setDisplayPrefs(const DisplayPrefs &prefs);
    // The latest shown correction age is past the threshold.
    bool correctionsLate() const { return late_; }
    // The receiver reports RTK information at all (state.rtk.seen).
    bool rtkAvailable() const { return available_; }

    // The watchdog's alarm colour (the views' error red, readable on light and dark palettes).
    static QColor alarmColor();

public slots:
    // Reads the model now (the timer calls this when a new epoch has arrived).
    void refresh();

signals:
    void availabilityChanged(bool available);
    void correctionsLateChanged(bool late);

private:
    DisplayPrefs prefs_;
    void updateWatchdog(std::optional<double> age);
    void poll();

    ReceiverStateModel *model_;
    QTimer *timer_;
    quint64 shownEpochs_ = ~quint64(0);
    bool available_ = false;
    bool late_ = false;
    std::optional<double> age_;

    QStackedWidget *stack_;
    QDoubleSpinBox *threshold_;
    QLabel *mode_, *watchdog_;
    QLabel *correctionAge_; // also the watchdog's
    // Every value label of the groups and how its text is written from the RTK state.
    struct Value {
        QLabel *label;
        QString (*text)(const RtkState &, UnitSystem);
    };
    std::vector<Value> values_;
};

} // namespace gnss::ui
