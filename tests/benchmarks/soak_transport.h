#pragma once
// SoakTransport: the soak program's receiver as a link, in place of the built-in simulator
// source: the standard sentences of SoakSky (20 Hz, about 60 satellites) interleaved with the
// proprietary output of the built-in simulated NV08C-RTK (RTK status, time marks, IMU attitude)
// and its answers to commands. Simulated time runs as fast as the GUI thread takes it: every
// pass of the event loop (a zero-interval timer) delivers slices of kSliceSeconds for
// kPassBudgetMs of real time, then the loop runs its timers and repaints before the next pass.
#include "link/transport.h"
#include "soak_sky.h"

#include <QTimer>

#include <memory>

namespace gnss {
class DialectRegistry;
namespace sim {
class Receiver;
}
} // namespace gnss

namespace gnss::soak {

class SoakTransport : public link::Transport {
    Q_OBJECT
public:
    // Simulated seconds per delivery (10 epochs).
    static constexpr double kSliceSeconds = 0.5;
    // Real milliseconds of slices per event-loop pass.
    static constexpr qint64 kPassBudgetMs = 40;

    SoakTransport(const DialectRegistry &registry, QObject *parent = nullptr);
    ~SoakTransport() override;

    bool open() override;
    void close() override;
    QString description() const override;
    int baud() const override;
    bool setBaud(int baud) override;

    double simulatedSeconds() const { return double(epoch_) / SoakSky::kRateHz; }
    int satellitesInView() const { return sky_.inView(); }
    // Stops advancing once this much simulated time has passed.
    void setEndSeconds(double s) { endSeconds_ = s; }

protected:
    bool writeBytes(const QByteArray &bytes) override;

private:
    void tick();
    void slice();

    const DialectRegistry &registry_;
    SoakSky sky_;
    std::unique_ptr<sim::Receiver> nvs_;
    std::int64_t epoch_ = 0;
    double endSeconds_ = 1e18;
    QByteArray partial_; // an NVS line not finished at the end of a slice
    QTimer timer_;
};

} // namespace gnss::soak
