#pragma once
// CompareModel: the receivers of a window compared live, epoch by epoch on UTC time
// (compare::Comparison), the matches of the last minutes kept for the Compare dock: its numbers
// (a compare::Report over that window), its plots and its export. The first receiver is the
// reference: every difference is another receiver minus it.
//
//   ReceiverStateModel::updated (each receiver, once per epoch) → Observation → Comparison
//     → a MatchRecord per time every receiver reported → the window (the last N minutes)
#include "compare/comparison.h"

#include <QColor>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QTimer>

#include <deque>
#include <memory>

namespace gnss::ui {

class ReceiverStateModel;

class CompareModel : public QObject {
    Q_OBJECT
public:
    struct Receiver {
        QPointer<ReceiverStateModel> state;
        QString name;
        QColor colour;
    };
    explicit CompareModel(QObject *parent = nullptr);
    ~CompareModel() override;

    // Starts over with these receivers (the first is the reference).
    void setReceivers(const QList<Receiver> &receivers);
    const QList<Receiver> &receivers() const { return receivers_; }
    // A receiver's name once it is known better (its model found).
    void setName(int receiver, const QString &name);

    // How much the window holds, in seconds of UTC time (default 300).
    void setWindowSeconds(int seconds);
    int windowSeconds() const { return windowSeconds_; }
    // The matches in the window, oldest first.
    const std::deque<compare::MatchRecord> &matches() const { return matches_; }
    // The numbers over the window (computed once per change).
    const compare::Report &report() const;
    // Every time all receivers reported, since setReceivers.
    std::size_t matchedEpochs() const;
    // Each receiver's latest observation (C/N0 side by side); null before its first.
    const compare::Observation *latest(int receiver) const;

    // The window as CSV (one row per match and receiver after the first) or as the JSON object
    // of gnss-cli compare --json (over the window).
    QByteArray csv() const;
    QByteArray json() const;

signals:
    // At most twice a second, after new matches (or a new set of receivers).
    void changed();

private:
    void observe(int receiver);
    void evict();
    std::vector<std::string> names() const;

    QList<Receiver> receivers_;
    QList<QMetaObject::Connection> connections_;
    std::unique_ptr<compare::Comparison> comparison_;
    std::vector<std::optional<compare::Observation>> latest_;
    std::deque<compare::MatchRecord> matches_;
    int windowSeconds_ = 300;
    mutable std::optional<compare::Report> report_;
    bool dirty_ = false;
    QTimer tick_;
};

} // namespace gnss::ui
