#pragma once
// DragGesture: what a left-button press on the log viewer's plot and track turns out to be, a
// click (released before it moved kClickSlop pixels) or a drag (the offset from where it began,
// once it moved that far, and on every move after).
#include <QMouseEvent>
#include <QPointF>

#include <cmath>
#include <optional>

namespace gnss::ui {

class DragGesture {
public:
    static constexpr int kClickSlop = 4; // pixels: a press that moves less is a click, not a drag

    // Begins on a left-button press; false (and nothing begun) for the other buttons.
    bool press(const QMouseEvent *e) {
        if (e->button() != Qt::LeftButton) return false;
        pressed_ = true;
        dragged_ = false;
        from_ = e->position();
        return true;
    }
    // The offset from the press, once the gesture is a drag; the distance that makes it one is
    // measured along x only (`horizontalOnly`) or in both directions.
    std::optional<QPointF> drag(const QMouseEvent *e, bool horizontalOnly) {
        if (!pressed_) return std::nullopt;
        const QPointF d = e->position() - from_;
        const double moved = horizontalOnly ? std::abs(d.x()) : std::hypot(d.x(), d.y());
        if (!dragged_ && moved < kClickSlop) return std::nullopt;
        dragged_ = true;
        return d;
    }
    // Ends the gesture: true when it was a click.
    bool release() {
        const bool click = pressed_ && !dragged_;
        pressed_ = false;
        return click;
    }

private:
    QPointF from_;
    bool pressed_ = false, dragged_ = false;
};

} // namespace gnss::ui
