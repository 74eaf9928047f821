#pragma once
// TimelinePanel: the log viewer's transport under the views. The strip of the whole log, and
// buttons (each with a shortcut, active only while a log is open) to play and pause, change the
// speed (0.1x to 100x, or as fast as the views draw), step an epoch, jump to the previous or
// next event, to the start or end, to a typed time, and to mark a range. It moves the cursor
// itself; playing and following a growing file are the application's (it owns the timers).
// While a log is being indexed it offers a Cancel button (Esc while the timeline has focus).
#include "logview/log_cursor.h"
#include "logview/log_range.h"
#include "logview/transport_icons.h"

#include <QWidget>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QToolButton;

namespace gnss::ui {

class TimelineStrip;

class TimelinePanel : public QWidget {
    Q_OBJECT
public:
    explicit TimelinePanel(LogCursor *cursor, QWidget *parent = nullptr);

    TimelineStrip *strip() const { return strip_; }
    // Speeds offered (0: as fast as possible).
    static const std::vector<double> &speeds();
    double speed() const;
    void setSpeed(double factor);
    void setPlaying(bool playing);
    bool playing() const;
    bool following() const;
    // Goes to a typed time ("10:42:00", "2024-03-15T10:42:00Z", "#1200"); false (and a word
    // beside the box) when it names no epoch of the log.
    bool goTo(const QString &text);
    // A word beside the Go to box (a start time the log does not hold, say).
    void showMessage(const QString &text);
    // Why a typed time names no epoch of `log` (before its start, after its end, a log without
    // times), with the log's first and last epoch, in the user's language.
    static QString refusalText(const logview::LogView &log, logview::TimePlace place,
                               const QString &typed);
    // Every action of the panel, for the window's menu.
    QList<QAction *> actions() const { return actions_; }
    // The words under the strip ("#1200 of 5000 · 10:42:00.000 · RTK fixed").
    QString positionText() const;
    // Indexing progress (fraction < 0: not indexing): shows or hides the Cancel button.
    void setIndexing(double fraction, const QString &text);
    QAction *cancelAction() const { return cancel_; }

signals:
    void playRequested(bool play);
    void speedChanged(double factor);
    void followRequested(bool follow);
    void cancelRequested(); // stop indexing the log being opened

protected:
    void changeEvent(QEvent *e) override;

private:
    void paintIcons();
    QAction *addAction(const QString &text, const QKeySequence &key, const char *name,
                       const std::function<void()> &run);
    void updateState();
    void step(long long delta);
    void jumpToEvent(bool forward);

    LogCursor *cursor_;
    TimelineStrip *strip_;
    QList<QAction *> actions_;
    QAction *play_ = nullptr;
    QAction *cancel_ = nullptr;
    QToolButton *cancelButton_ = nullptr;
    std::vector<std::pair<QAction *, TransportIcon>> icons_;
    QComboBox *speed_;
    QLineEdit *goTo_;
    QCheckBox *follow_;
    QLabel *position_, *message_;
};

} // namespace gnss::ui
