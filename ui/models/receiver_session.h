#pragma once
// ReceiverSession: everything one receiver needs, in one object. It owns the receiver's link half
// (session::ReceiverLink: source, connection with its one decoder, command queue and recorder,
// baud and vendor detection, settings engine, corrections forwarder) and the models the docks
// read (state, satellites, message statistics, console), fed from that link's decoder by a
// ModelFeed. The window holds a list of these; a dock is given the session it shows.
#include "models/model_feed.h"
#include "models/signal_history_model.h"

#include <QColor>
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
    // C/N0 of each signal over the last minutes, and the polar C/N0 map.
    SignalHistoryModel *signalHistory() const { return history_; }
    const SessionModels &models() const { return models_; }

    // The dialect the receiver speaks (that of its last sentence; null: none known yet).
    const Dialect *dialect() const { return feed_->dialect(); }
    const LinkCounters &counters() const { return feed_->counters(); }

    // What the user calls it: the name given (renamed), else the receiver's model (or dialect)
    // and where it is ("NV08C-RTK /dev/ttyUSB0").
    QString name() const;
    // The model (or dialect) alone, or the name given: short enough for a dock's title.
    QString shortName() const;
    QString givenName() const { return givenName_; }
    // Empty: named after the model and port again.
    void setGivenName(const QString &name);
    // The colour it is drawn in wherever several receivers are (the window gives each its own).
    QColor colour() const { return colour_; }
    void setColour(const QColor &c) { colour_ = c; }

signals:
    void dialectChanged(const gnss::Dialect *dialect);

private:
    QString givenName_;
    mutable QString knownName_, knownSource_;
    mutable bool knownFromModel_ = false;
    SignalHistoryModel *history_ = nullptr;
    QColor colour_;
    SessionModels models_;
    ModelFeed *feed_;
    session::ReceiverLink *link_;
};

} // namespace gnss::ui
