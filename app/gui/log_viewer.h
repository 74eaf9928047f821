#pragma once
// LogViewer: the offline log viewer's controller. It owns the open log (the engine's LogView,
// indexing on its worker thread) and the one cursor every log view follows, and publishes the
// receiver state at the cursor into the same models the live link feeds, so every dock (sky plot,
// signal levels, fix, RTK, satellites, attitude, receiver, console, statistics, charts) shows
// that moment. It plays (paced by the log's own times, 0.1x to 100x, or as fast as the views
// draw), follows a file still being written (what it gained indexed on a worker thread), and
// exports on a worker thread. Nothing on the GUI thread waits for the disk or for indexing.
#include "logview/log_cursor.h"
#include "logview/log_lines_model.h"
#include "models/receiver_session.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QThread>
#include <QTimer>
#include <atomic>
#include <memory>

namespace gnss::app {

class LogViewer : public QObject {
    Q_OBJECT
public:
    enum class Export { Gpx, Kml, Csv, Nmea, StatsJson, EventsCsv };

    LogViewer(const DialectRegistry &registry, ui::SessionModels models, QObject *parent = nullptr);
    ~LogViewer() override;

    // Opens a log (a log open before is closed); indexing starts at once, the first epoch is
    // shown as soon as it is read.
    // `at`: a time or epoch ("10:42:00", "#1200") the cursor goes to once indexed.
    void open(const QString &path, const QString &at = {});
    void close();
    // Stops indexing the log being opened (the log stays open, cancelled: statusText() says so;
    // opening it again indexes it afresh). Nothing when it is not being indexed.
    void cancelIndexing();
    bool indexing() const;
    bool isOpen() const { return view_ != nullptr; }
    // Indexed, and the cursor and views know it.
    bool ready() const { return view_ && readyNoted_; }
    QString path() const { return path_; }
    ui::LogCursor *cursor() { return &cursor_; }
    // The console's rows while a log is open: every line of the file, the cursor's marked.
    ui::LogLinesModel *lines() { return &lines_; }
    const logview::LogView *view() const { return view_.get(); }
    // The open log, for work that may outlive it being closed (play out).
    std::shared_ptr<const logview::LogView> shared() const { return view_; }

    // The status bar's words: what is open, how far indexing is, or what went wrong.
    QString statusText() const;
    // The vendor dialect heard last at the cursor (nullptr: standard NMEA only).
    const Dialect *dialectAtCursor() const;
    bool failed() const;

    void setPlaying(bool on);
    bool playing() const { return playTimer_.isActive(); }
    void setSpeed(double factor); // 0: as fast as possible
    double speed() const { return speed_; }
    void setFollowing(bool on);
    bool following() const { return followTimer_.isActive(); }
    // A followed file's growth is being indexed (on a worker thread).
    bool followBusy() const { return followBusy_; }
    // The engine's options for the logs opened from now on (tests hook into following).
    void setViewOptions(logview::LogViewOptions options) { viewOptions_ = std::move(options); }

    // Writes the selected range (or the whole log) to `path` on a worker thread;
    // exportFinished() says how it went. False (and `why`) when nothing can be exported yet.
    bool exportTo(Export format, const QString &path, QString *why = nullptr);
    bool exporting() const { return exporting_; }
    static std::optional<Export> formatOfSuffix(const QString &suffix);

    // Publishes the state at epoch k now (the cursor does this on every move).
    void publish(std::size_t k);
    // How long the last publish took, ms (for the status bar's tooltip and the benchmark).
    double lastPublishMs() const { return lastPublishMs_; }

signals:
    void statusChanged();
    void progress(double fraction, const QString &text);
    void indexed(); // ready (or grown, when following)
    // The time or epoch to start at (--at) names none of the log's: the cursor stays at #0.
    void startRefused(const QString &why);
    void playingChanged(bool playing);
    void exportFinished(bool ok, const QString &message);

private:
    void poll();
    void tick();
    void follow();
    void showFirstEpoch();
    void publishMessages();
    void showCursorLines(std::size_t k);
    void countLines();
    qint64 epochMs(std::size_t k) const;
    void anchorPlay();
    // Runs `work` on a worker thread and `done` with its result back on this thread (dropped
    // when another log was opened meanwhile).
    template <class Work, class Done> void runAsync(Work work, Done done);

    const DialectRegistry &registry_;
    ui::SessionModels models_;
    std::shared_ptr<logview::LogView> view_; // shared with the workers that read it
    ui::LogCursor cursor_;
    ui::LogLinesModel lines_;
    QString path_, startAt_;
    QTimer pollTimer_, playTimer_, followTimer_;
    bool firstShown_ = false, readyNoted_ = false, cancelling_ = false, followBusy_ = false;
    logview::LogViewOptions viewOptions_;
    std::size_t lastPublished_ = 0;
    bool havePublished_ = false, advancing_ = false;
    double speed_ = 1;
    QElapsedTimer playClock_;
    std::size_t playEpoch_ = 0;
    qint64 playLogMs_ = 0;
    double lastPublishMs_ = 0;
    bool exporting_ = false;
    quint64 generation_ = 0;                 // bumped when the log changes
    quint64 messagesAsked_ = 0;              // the latest message-statistics request
    QTimer messagesDelay_;                   // a range being dragged is counted once it rests
    std::vector<QPointer<QThread>> workers_; // joined by the destructor
    std::shared_ptr<std::atomic<bool>> stop_ = std::make_shared<std::atomic<bool>>(false);
};

} // namespace gnss::app
