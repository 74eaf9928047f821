#pragma once
// TimelineStrip: the whole log as one strip under the views. Each pixel column is coloured by the
// fix type most of its epochs had (fix colours); data gaps are dark ticks above, checksum-error
// bursts red ticks below, events small marks on top; the selected range is shaded and the cursor
// is a line. Click or drag to seek; Shift+drag selects a range. While the log is being indexed it
// shows the progress instead.
#include "logview/log_cursor.h"

#include <QWidget>
#include <vector>

namespace gnss::ui {

class TimelineStrip : public QWidget {
    Q_OBJECT
public:
    explicit TimelineStrip(LogCursor *cursor, QWidget *parent = nullptr);

    // Indexing progress, 0..1, with a word ("Indexing…"); fraction < 0 hides the bar (the word
    // stays while no epoch is shown: "indexing cancelled", "no NMEA found").
    void setProgress(double fraction, const QString &text);

    // Pixel column of an epoch and the epoch of a pixel column (for tests and the mouse).
    int xOfEpoch(std::size_t epoch) const;
    std::size_t epochAtX(int x) const;

    struct Bin {
        quint8 fix = 0;      // dominant FixType
        bool any = false;    // the column holds epochs
        bool gap = false;    // a data gap or link gap begins in it
        bool errors = false; // checksum or decode errors, junk
        bool event = false;  // an event falls in it
        bool fill = false;   // no epoch of its own: the one before it goes on
    };
    const std::vector<Bin> &bins() const { return bins_; }

    QSize sizeHint() const override { return {600, 34}; }
    QSize minimumSizeHint() const override { return {120, 28}; }

protected:
    void paintEvent(QPaintEvent *) override;
    void resizeEvent(QResizeEvent *) override;
    void mousePressEvent(QMouseEvent *e) override;
    void mouseMoveEvent(QMouseEvent *e) override;
    void mouseReleaseEvent(QMouseEvent *e) override;
    bool event(QEvent *e) override;

private:
    void rebuild();
    QRect stripRect() const;

    LogCursor *cursor_;
    std::vector<Bin> bins_;
    double progress_ = -1;
    QString progressText_;
    bool selecting_ = false, dragging_ = false;
    std::size_t selectFrom_ = 0;
};

} // namespace gnss::ui
