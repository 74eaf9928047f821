#pragma once
// ReceiverSession: everything one receiver needs, in one object. It owns the receiver's link half
// (session::ReceiverLink: source, connection with its one decoder, command queue and recorder,
// baud and vendor detection, settings engine, corrections forwarder) and the models the docks
// read (state, satellites, message statistics, console), fed from that link's decoder by a
// ModelFeed. The window holds a list of these; a dock is given the session it shows.
#include "models/model_feed.h"

#include <QObject>
#include <QString>

namespace gnss::link {
class TransportFactory;
}
namespace gnss::session {
class ReceiverLink;
}

namespace gnss::ui {

class ReceiverSession : public QObject {
    Q_OBJECT
public:
    ReceiverSession(const DialectRegistry &registry, const link::TransportFactory &transports,
                    QObject *parent = nullptr);
    ~ReceiverSession() override;

    session::ReceiverLink *link() const { return link_; }
    ModelFeed *feed() const { return feed_; }
    ReceiverStateModel *state() const { return models_.state; }
    SatelliteModel *satellites() const { return models_.satellites; }
    MessageStatsModel *messages() const { return models_.messages; }
    ConsoleModel *console() const { return models_.console; }
    const SessionModels &models() const { return models_; }

    // The dialect the receiver speaks (that of its last sentence; null: none known yet).
    const Dialect *dialect() const { return feed_->dialect(); }
    const LinkCounters &counters() const { return feed_->counters(); }

signals:
    void dialectChanged(const gnss::Dialect *dialect);

private:
    SessionModels models_;
    ModelFeed *feed_;
    session::ReceiverLink *link_;
};

} // namespace gnss::ui
