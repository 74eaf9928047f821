#pragma once
// TtffCampaign: a time-to-first-fix campaign on one receiver link. For each kind of start asked
// (cold, warm, hot) it runs N restarts, each with the restart command of the receiver's dialect
// record (its actions: never a sticky bit), and measures on the host's clock, from the moment the
// command is written, the first position, 2D, 3D (the TTFF), DGNSS, RTK float and fixed
// (qualify::RunTracker). Before a warm or hot start the receiver holds a 3D fix long enough to
// have its ephemerides. A run that never fixes ends at its timeout and is counted, and so does a
// warm or hot run whose receiver gives no fix to hold within the timeout (its restart not sent);
// a link lost mid-run marks the run lost, and the campaign goes on once the link is back. With
// several receivers (setBarrier), one that is ready waits for the others at most a run's timeout,
// then restarts alone. Nothing blocks.
#include "qualify/ttff.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace gnss {
struct Epoch;
class EpochAssembler;
struct SentenceEvent;
namespace link {
class Connection;
}
} // namespace gnss

namespace gnss::qualify {

class TtffCampaign : public QObject {
    Q_OBJECT
public:
    struct Plan {
        std::vector<ReceiverAction> starts; // each kind `runs` times, in this order
        int runs = 10;
        int timeoutMs = 180'000; // a run's limit
        int pauseMs = 5'000;     // between runs
        int holdMs = 30'000;     // a 3D fix held this long before a warm or hot start
        std::optional<std::pair<double, double>> reference; // lat, lon: the first fix's distance
    };

    // Why the campaign cannot run on a receiver of `dialect` (a kind it has no command for,
    // naming those it has; no dialect known); empty when it can.
    static QString refusal(const Dialect *dialect, const std::vector<ReceiverAction> &starts);

    TtffCampaign(link::Connection *connection, const Dialect *dialect, Plan plan,
                 QObject *parent = nullptr);
    ~TtffCampaign() override;

    // With several receivers the same restarts at the same time: each campaign, when it would
    // restart, waits (readyToRestart()) until go() is called — the caller calls it on all once
    // all are ready — or a run's timeout has passed. Off by default (restarts as soon as each is
    // ready).
    void setBarrier(bool on) { barrier_ = on; }
    bool readyToGo() const { return phase_ == Phase::Ready; }
    bool waitingForLink() const { return phase_ == Phase::WaitingForLink; }
    void go();

    void start();
    void cancel();
    bool running() const { return phase_ != Phase::Done; }
    const std::vector<TtffRun> &runs() const { return runs_; }
    int totalRuns() const { return int(plan_.starts.size()) * plan_.runs; }
    // "cold 3 of 20: waiting for a 3D fix, 12.4 s" (what it does now, in words).
    QString stateText() const;

signals:
    void progress(const QString &text);
    void runFinished(const gnss::qualify::TtffRun &run);
    void finished(bool cancelled);
    // Every epoch the receiver gives during the campaign (its positions between runs are what
    // the accuracy against the reference is measured on).
    void epoch(const gnss::Epoch &e);
    void readyToRestart();

private:
    enum class Phase { Idle, Settling, Ready, Restarting, Running, Pausing, WaitingForLink, Done };
    void onSentence(const SentenceEvent &ev);
    void onEpoch(const Epoch &e);
    void nextRun();
    void restart();
    void restartOrWait();
    void endRun(RunOutcome outcome);
    void tick();
    void say();

    link::Connection *connection_;
    const Dialect *dialect_;
    Plan plan_;
    std::unique_ptr<EpochAssembler> assembler_;
    std::vector<TtffRun> runs_;
    std::optional<RunTracker> tracker_;
    Phase phase_ = Phase::Idle;
    std::size_t startIndex_ = 0;
    int runIndex_ = 0; // 1.. within the current kind
    int commandId_ = -1;
    QElapsedTimer sinceCommand_, inPhase_, fixHeld_;
    bool fixNow_ = false;
    QTimer tick_;
    bool cancelled_ = false;
    bool barrier_ = false;
};

} // namespace gnss::qualify
