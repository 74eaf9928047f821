#pragma once
// ComparePlot: one receiver against the reference over the Compare dock's window, drawn with
// QPainter (cheap at 10 Hz for several receivers): the east/north scatter of the position
// difference with its CEP50 and CEP95 circles, the horizontal and vertical difference over time,
// and a fix-type strip per receiver on the same time axis.
#include <QWidget>

namespace gnss::ui {

class CompareModel;

class ComparePlot : public QWidget {
    Q_OBJECT
public:
    explicit ComparePlot(const CompareModel *model, QWidget *parent = nullptr);
    // Which receiver (1..) is drawn against the reference.
    void setReceiver(int receiver);
    int receiver() const { return receiver_; }
    QSize minimumSizeHint() const override { return {200, 80}; }

protected:
    void paintEvent(QPaintEvent *) override;

private:
    void paintScatter(QPainter &p, const QRectF &r);
    void paintSeries(QPainter &p, const QRectF &r);
    void paintFixes(QPainter &p, const QRectF &r);

    const CompareModel *model_;
    int receiver_ = 1;
};

} // namespace gnss::ui
