#pragma once
// TransportFactory: makes the Transport for a SourceSpec. Serial ports, TCP servers, gpsd and
// recorded logs are built in; the application adds what the link library does not know (the
// built-in simulator) with add(). The GUI and every gnss-cli command use one
// factory, so each command accepts every source the application knows.
#include "link/source_spec.h"
#include "link/transport.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <map>
#include <memory>

namespace gnss::link {

class TransportFactory {
public:
    // Makes the transport (not opened), or nullptr with `error` set when the spec is wrong.
    using Maker = std::function<std::unique_ptr<Transport>(const SourceSpec &, QString *error)>;

    TransportFactory(); // serial, TCP, gpsd and replay
    // `names`: the names a source of this kind takes, when they are a closed list (the dialects
    // a simulator plays), for source lists and option checks.
    void add(SourceSpec::Kind kind, Maker maker, QStringList names = {});
    bool supports(SourceSpec::Kind kind) const { return makers_.count(kind) != 0; }
    QStringList names(SourceSpec::Kind kind) const;
    std::unique_ptr<Transport> make(const SourceSpec &spec, QString *error = nullptr) const;

private:
    std::map<SourceSpec::Kind, Maker> makers_;
    std::map<SourceSpec::Kind, QStringList> names_;
};

} // namespace gnss::link
