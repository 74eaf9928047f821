#pragma once
// SimulatorTransport: the built-in receiver simulator (gnss_sim) as a link, in process, driven by
// a timer: commands go to the simulated receiver, its output comes back as received bytes. The
// line speed set here is the host side's: at another speed than the receiver's, output is garbage
// (as on a real UART), so baud detection and baud changes work as with hardware.
#include "link/transport.h"

#include <QElapsedTimer>
#include <QTimer>

#include <memory>

namespace gnss::sim {
class Receiver;
class SimulatorTable;
} // namespace gnss::sim

namespace gnss::link {

class SimulatorTransport : public Transport {
    Q_OBJECT
public:
    // The simulated receiver of `dialect` ("nmea", "nvs", ...) from `simulators` (which outlives
    // the transport); `lineBaud` 0 = the receiver's own.
    SimulatorTransport(const sim::SimulatorTable &simulators, QString dialect,
                       std::uint32_t seed = 1, int lineBaud = 0, QObject *parent = nullptr);
    ~SimulatorTransport() override;

    bool open() override;
    void close() override;
    QString description() const override;
    int baud() const override { return lineBaud_; }
    bool setBaud(int baud) override;

    // Simulated seconds per real second.
    void setSpeed(double factor) { speed_ = factor; }
    sim::Receiver *receiver() const { return receiver_.get(); }

protected:
    bool writeBytes(const QByteArray &bytes) override;

private:
    void tick();

    const sim::SimulatorTable &simulators_;
    QString dialect_;
    std::uint32_t seed_;
    int lineBaud_;
    double speed_ = 1.0;
    std::unique_ptr<sim::Receiver> receiver_;
    QElapsedTimer clock_;
    QTimer timer_;
};

} // namespace gnss::link
