#pragma once
// FixView: the fix at a glance — badge, position (degrees, degrees and minutes, or DMS), heights
// above sea level and ellipsoid, satellites, DOPs, time, speed and course, corrections, in the
// user's units and time zone. Refreshed on a timer.
#include "models/value_format.h"

#include <QTimer>
#include <QWidget>

class QLabel;
class QComboBox;
class QGridLayout;

namespace gnss::ui {

class ReceiverStateModel;

class FixView : public QWidget {
    Q_OBJECT
public:
    explicit FixView(ReceiverStateModel *model, QWidget *parent = nullptr);
    void setDisplayPrefs(const DisplayPrefs &prefs);
    const DisplayPrefs &displayPrefs() const { return prefs_; }
    void refresh(); // what the timer does

signals:
    // The user chose another coordinate format in the view's own box (the preferences follow).
    void coordinateFormatChosen(CoordinateFormat format);

private:
    QLabel *addRow(const QString &name, const QString &objectName);
    ReceiverStateModel *model_;
    QTimer timer_;
    bool dirty_ = true;
    DisplayPrefs prefs_;
    QComboBox *format_ = nullptr;
    QLabel *badge_ = nullptr;
    QGridLayout *grid_ = nullptr;
    QLabel *lat_, *lon_, *altMsl_, *altEll_, *sats_, *dops_, *utc_, *speed_, *course_, *corrAge_,
            *base_;
};

} // namespace gnss::ui
