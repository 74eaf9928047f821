#include "link/transport_factory.h"

#include "core/baud_rates.h"
#include "link/gpsd_transport.h"
#include "link/replay_transport.h"
#include "link/serial_transport.h"
#include "link/tcp_transport.h"

#include <QCoreApplication>

namespace gnss::link {

namespace {
QString tr(const char *text) {
    return QCoreApplication::translate("gnss::link::TransportFactory", text);
}
} // namespace

TransportFactory::TransportFactory() {
    add(SourceSpec::Kind::Serial, [](const SourceSpec &s, QString *) {
        // Baud 0 (detect) opens at the most likely rate; the detector changes it.
        return std::make_unique<SerialTransport>(
                SerialSettings{s.name, s.baud > 0 ? s.baud : kDefaultSerialBaud});
    });
    add(SourceSpec::Kind::Tcp, [](const SourceSpec &s, QString *error) {
        QString host;
        quint16 port = 0;
        if (!TcpTransport::parseHostPort(s.name, host, port)) {
            if (error) *error = tr("a TCP source is HOST:PORT, got '%1'").arg(s.name);
            return std::unique_ptr<Transport>();
        }
        return std::unique_ptr<Transport>(std::make_unique<TcpTransport>(host, port));
    });
    add(SourceSpec::Kind::Gpsd, [](const SourceSpec &s, QString *error) {
        GpsdTransport::Target target;
        if (!GpsdTransport::parseTarget(s.name, target, error)) return std::unique_ptr<Transport>();
        return std::unique_ptr<Transport>(std::make_unique<GpsdTransport>(target));
    });
    add(SourceSpec::Kind::Replay, [](const SourceSpec &s, QString *) {
        auto r = std::make_unique<ReplayTransport>(
                s.name, s.asFast ? ReplayTransport::Timing::AsFast : ReplayTransport::Timing::Auto);
        if (s.speed > 0) r->setSpeed(s.speed);
        return r;
    });
}

void TransportFactory::add(SourceSpec::Kind kind, Maker maker, QStringList names) {
    makers_[kind] = std::move(maker);
    names_[kind] = std::move(names);
}

QStringList TransportFactory::names(SourceSpec::Kind kind) const {
    const auto it = names_.find(kind);
    return it == names_.end() ? QStringList() : it->second;
}

std::unique_ptr<Transport> TransportFactory::make(const SourceSpec &spec, QString *error) const {
    if (!spec.valid()) {
        if (error) *error = tr("no source given");
        return nullptr;
    }
    const auto it = makers_.find(spec.kind);
    if (it == makers_.end()) {
        if (error)
            *error = tr("%1: this program cannot open such a source").arg(spec.displayName());
        return nullptr;
    }
    return it->second(spec, error);
}

} // namespace gnss::link
