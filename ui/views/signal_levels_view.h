#pragma once
// SignalLevelsView: one SNR bar per satellite and signal, grouped by constellation and signal,
// used satellites filled, tracked ones outlined, ids below. Repaints on a timer, from the model.
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
    };
    // The bars the next paint draws, in order (for tests).
    QVector<Bar> layoutBars() const;

    QSize sizeHint() const override { return {600, 220}; }
    QSize minimumSizeHint() const override { return {200, 120}; }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    QRectF plotArea() const;
    SatelliteModel *model_;
    QTimer repaintTimer_;
    bool dirty_ = true;
};

} // namespace gnss::ui
