#include "app_transports.h"

#include "receiver.h"
#include "simulator_transport.h"

namespace gnss::app {

link::TransportFactory makeTransportFactory(const DialectRegistry &registry) {
    link::TransportFactory f;
    f.add(link::SourceSpec::Kind::Simulator, [&registry](const link::SourceSpec &s, QString *) {
        auto t = std::make_unique<link::SimulatorTransport>(registry, s.name, 1, s.baud);
        if (s.speed > 0) t->setSpeed(s.speed);
        return t;
    });
    return f;
}

QStringList simulatedDialects(const DialectRegistry &registry) {
    QStringList out;
    for (std::string_view id : sim::simulatedDialects(registry))
        out << QString::fromUtf8(id.data(), qsizetype(id.size()));
    return out;
}

} // namespace gnss::app
