#include "link/source_spec.h"

#include <QCoreApplication>

namespace gnss::link {

QString SourceSpec::toString() const {
    switch (kind) {
    case Kind::Serial: return QStringLiteral("serial:%1@%2").arg(name).arg(baud);
    case Kind::Tcp: return QStringLiteral("tcp:%1").arg(name);
    case Kind::Replay: return QStringLiteral("replay:%1").arg(name);
    case Kind::Simulator: return QStringLiteral("sim:%1").arg(name);
    case Kind::Gpsd: return QStringLiteral("gpsd://%1").arg(name);
    case Kind::None: break;
    }
    return {};
}

SourceSpec SourceSpec::fromString(const QString &s) {
    SourceSpec spec;
    const int colon = s.indexOf(':');
    if (colon < 0) return spec;
    const QString kind = s.left(colon), rest = s.mid(colon + 1);
    if (kind == QLatin1String("serial")) {
        const int at = rest.lastIndexOf('@');
        spec.kind = Kind::Serial;
        spec.name = at < 0 ? rest : rest.left(at);
        spec.baud = at < 0 ? 0 : rest.mid(at + 1).toInt();
    } else if (kind == QLatin1String("tcp")) {
        spec.kind = Kind::Tcp;
        spec.name = rest;
    } else if (kind == QLatin1String("replay")) {
        spec.kind = Kind::Replay;
        spec.name = rest;
    } else if (kind == QLatin1String("sim")) {
        spec.kind = Kind::Simulator;
        spec.name = rest;
    } else if (kind == QLatin1String("gpsd")) {
        // The URL form, gpsd://HOST[:PORT][/DEVICE]; "gpsd:HOST" is taken too.
        spec.kind = Kind::Gpsd;
        spec.name = rest.startsWith(QLatin1String("//")) ? rest.mid(2) : rest;
    }
    return spec;
}

QString SourceSpec::displayName() const {
    // (translate() with the context spelled out: lupdate files it under the one used here.)
    switch (kind) {
    case Kind::Serial:
        return baud ? QCoreApplication::translate("SourceSpec", "%1 at %2 baud").arg(name).arg(baud)
                    : QCoreApplication::translate("SourceSpec", "%1 (baud: auto)").arg(name);
    case Kind::Tcp: return QCoreApplication::translate("SourceSpec", "TCP %1").arg(name);
    case Kind::Replay: return QCoreApplication::translate("SourceSpec", "Replay %1").arg(name);
    case Kind::Simulator:
        return QCoreApplication::translate("SourceSpec", "Simulated %1").arg(name);
    case Kind::Gpsd: return QCoreApplication::translate("SourceSpec", "gpsd %1").arg(name);
    case Kind::None: break;
    }
    return QCoreApplication::translate("SourceSpec", "No source");
}

QString SourceSpec::place() const {
    switch (kind) {
    case Kind::Serial:
    case Kind::Tcp: return name;
    case Kind::Replay: return name.mid(name.lastIndexOf('/') + 1);
    case Kind::Simulator: return QCoreApplication::translate("SourceSpec", "simulated");
    case Kind::Gpsd: return QCoreApplication::translate("SourceSpec", "gpsd %1").arg(name);
    case Kind::None: break;
    }
    return {};
}

} // namespace gnss::link
