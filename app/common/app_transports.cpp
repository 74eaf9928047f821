#include "common/app_transports.h"

#include "common/simulator_transport.h"

namespace gnss::app {

link::TransportFactory makeTransportFactory(const sim::SimulatorTable &simulators) {
    link::TransportFactory f;
    f.add(
            link::SourceSpec::Kind::Simulator,
            [&simulators](const link::SourceSpec &s, QString *) {
                auto t = std::make_unique<link::SimulatorTransport>(simulators, s.name, 1, s.baud);
                if (s.speed > 0) t->setSpeed(s.speed);
                return t;
            },
            simulatedDialects(simulators));
    return f;
}

QStringList simulatedDialects(const sim::SimulatorTable &simulators) {
    QStringList out;
    for (std::string_view id : simulators.dialects())
        out << QString::fromUtf8(id.data(), qsizetype(id.size()));
    return out;
}

} // namespace gnss::app
