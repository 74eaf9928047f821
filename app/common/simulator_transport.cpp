#include "common/simulator_transport.h"

#include "sim/simulator_table.h"

namespace gnss::link {

// The simulated receiver's bytes come in slices of 20 ms, as a serial driver hands them over.
constexpr int kSimulatorTickMs = 20;

SimulatorTransport::SimulatorTransport(const sim::SimulatorTable &simulators, QString dialect,
                                       std::uint32_t seed, int lineBaud, QObject *parent)
    : Transport(parent), simulators_(simulators), dialect_(std::move(dialect)), seed_(seed),
      lineBaud_(lineBaud) {
    timer_.setInterval(kSimulatorTickMs);
    connect(&timer_, &QTimer::timeout, this, &SimulatorTransport::tick);
}

SimulatorTransport::~SimulatorTransport() = default;

bool SimulatorTransport::open() {
    sim::SimOptions options;
    options.seed = seed_;
    // The built-in receiver is a demonstration: an RTK rover shows RTK without a caster.
    options.internalBase = true;
    receiver_ = simulators_.make(dialect_.toStdString(), options);
    if (!receiver_) {
        fail(tr("The simulator has no receiver of dialect '%1'").arg(dialect_), false);
        return false;
    }
    if (lineBaud_ <= 0) lineBaud_ = receiver_->baud();
    receiver_->setLineBaud(lineBaud_);
    clock_.start();
    timer_.start();
    setState(State::Open);
    return true;
}

void SimulatorTransport::close() {
    timer_.stop();
    setState(State::Closed);
}

QString SimulatorTransport::description() const {
    return tr("simulated %1 receiver at %2 baud").arg(dialect_).arg(lineBaud_);
}

bool SimulatorTransport::setBaud(int baud) {
    lineBaud_ = baud;
    if (receiver_) receiver_->setLineBaud(baud);
    return true;
}

bool SimulatorTransport::writeBytes(const QByteArray &bytes) {
    if (!receiver_) return false;
    receiver_->receive(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    return true;
}

void SimulatorTransport::tick() {
    if (!receiver_) return;
    const qint64 ns = clock_.nsecsElapsed();
    clock_.start();
    receiver_->advance(static_cast<double>(ns) / 1e9 * speed_);
    const std::string out = receiver_->takeOutput();
    if (!out.empty()) emit bytesReceived(QByteArray::fromStdString(out));
    if (receiver_->hungUp()) {
        timer_.stop();
        fail(tr("The simulated receiver hung up"), true);
    }
}

} // namespace gnss::link
