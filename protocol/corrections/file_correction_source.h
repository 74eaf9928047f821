#pragma once
// FileCorrectionSource: a recorded RTCM file played at the pace it was recorded (see
// rtcm_file_plan.h: grouped by MSM epoch, or one 1005 a second), faster or slower by a speed
// factor, once or in a loop. For trying a receiver's RTK without a base, and for tests.
// The file is read when started; groups are sent from a timer, never by waiting.
#include "corrections/correction_source.h"
#include "corrections/rtcm_file_plan.h"

#include <QElapsedTimer>

namespace gnss::corrections {

class FileCorrectionSource : public CorrectionSource {
    Q_OBJECT
public:
    explicit FileCorrectionSource(QString path, QObject *parent = nullptr);
    ~FileCorrectionSource() override;

    QString description() const override; // the file's name
    // Simulated seconds per real second (2 = twice as fast); > 0.
    void setSpeed(double speed);
    double speed() const { return speed_; }
    // Starts again from the beginning at the end.
    void setLoop(bool loop) { loop_ = loop; }
    // The plan of the last start (groups, frames, how it was timed).
    const PlaybackPlan &plan() const { return plan_; }

protected:
    void openConnection() override;
    void closeConnection() override;

private:
    void sendDue();

    QString path_;
    double speed_ = 1.0;
    bool loop_ = false;
    QByteArray bytes_;
    PlaybackPlan plan_;
    std::size_t next_ = 0;
    double origin_ = 0; // playback time (ms) of the plan's start in this round
    QElapsedTimer clock_;
    QTimer timer_;
};

} // namespace gnss::corrections
