#pragma once
// DeviationView: the deviation plot (issue 8). Positions in metres east/north of their mean or of
// a reference the user types, coloured by fix type, with CEP50, CEP95 and 2DRMS circles and
// figures, autoscaled axes and a scale bar. The statistics live in PositionScatter; this widget
// collects one position per epoch and repaints on a 10 Hz timer when something changed.
#include "models/position_scatter.h"
#include "models/value_format.h"

#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTimer;

namespace gnss::ui {

class ReceiverStateModel;

class DeviationView : public QWidget {
    Q_OBJECT
public:
    explicit DeviationView(ReceiverStateModel *model, QWidget *parent = nullptr);

    const PositionScatter &scatter() const { return scatter_; }
    // Positions kept (default 3600).
    int capacity() const;
    void setCapacity(int n);
    // Centre on a typed reference ("55.75123456 N", "-37.6", "37.6 E"); an empty text returns to
    // the mean. Returns false (and keeps the mean) when the text is not a latitude/longitude.
    bool setReference(const QString &lat, const QString &lon);

    // Parses degrees with an optional hemisphere letter (N/S/E/W) or sign; nullopt when invalid
    // or out of range (90 for latitude, 180 for longitude).
    static std::optional<double> parseDegrees(const QString &text, bool latitude);

    // Lengths in the user's units (the plot's axes and scale bar too), centre coordinates in
    // their format.
    void setDisplayPrefs(const DisplayPrefs &prefs);

public slots:
    void reset();
    // Updates the figures and repaints now (the timer does this when a position arrived).
    void refresh();

private:
    class Canvas;
    void takeEpoch();
    void applyReference();

    ReceiverStateModel *model_;
    PositionScatter scatter_;
    QTimer *timer_;
    bool dirty_ = true;
    Canvas *canvas_;
    DisplayPrefs prefs_;
    QCheckBox *useRef_;
    QLineEdit *refLat_, *refLon_;
    QSpinBox *capacity_;
    QPushButton *reset_;
    QLabel *count_, *cep50_, *cep95_, *drms2_, *offset_, *centre_, *refStatus_;
};

} // namespace gnss::ui
