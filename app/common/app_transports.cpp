#include "app_transports.h"

#include "receiver.h"
#include "simulator_transport.h"

namespace gnss::app {

link::TransportFactory makeTransportFactory() {
    link::TransportFactory f;
    f.add(link::SourceSpec::Kind::Simulator, [](const link::SourceSpec &s, QString *) {
        auto t = std::make_unique<link::SimulatorTransport>(s.name, 1, s.baud);
        if (s.speed > 0) t->setSpeed(s.speed);
        return t;
    });
    return f;
}

QStringList simulatedDialects() {
    QStringList out;
    for (std::string_view id : sim::simulatedDialects())
        out << QString::fromUtf8(id.data(), qsizetype(id.size()));
    return out;
}

} // namespace gnss::app
