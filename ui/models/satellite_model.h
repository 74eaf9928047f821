#pragma once
// SatelliteModel: the satellites in view, one row per (constellation, PRN, signal), updated once
// per epoch. The sky plot and the signal-level bars are two views of this one model.
//
// A satellite that drops out of view stays (greyed, "last seen") for a while before it is removed;
// recent positions are kept per satellite for the sky plot's tracks.
#include "state/epoch.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QPointF>
#include <deque>
#include <vector>

namespace gnss::ui {

struct SatelliteRow {
    SatelliteRef sat;
    int signalId = 0;
    std::optional<int> elevation, azimuth, snr;
    bool used = false;
    bool inView = true;    // in the latest epoch
    qint64 lastSeenMs = 0; // host time
};

struct TrackPoint {
    qint64 ms;
    float azimuth, elevation;
};

class SatelliteModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { System, Prn, Signal, Elevation, Azimuth, Snr, Used, LastSeen, ColumnCount };
    enum Role {
        ConstellationRole = Qt::UserRole + 1, // int(Constellation)
        PrnRole,
        SignalRole,
        ElevationRole, // QVariant() when unknown
        AzimuthRole,
        SnrRole,
        UsedRole,
        InViewRole,
        LabelRole, // "G05", "G05 L5"
    };

    explicit SatelliteModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation o, int role = Qt::DisplayRole) const override;

    // Applies one epoch's sky (host time nowMs).
    void update(const Epoch &epoch, qint64 nowMs);
    void clear();

    const std::vector<SatelliteRow> &rows() const { return rows_; }
    // Track of one row's satellite (positions over the last trackWindow()), oldest first.
    const std::deque<TrackPoint> *track(const SatelliteRow &row) const;
    qint64 trackWindowMs() const { return trackWindowMs_; }
    void setTrackWindowMs(qint64 ms) { trackWindowMs_ = ms; }
    // How long a satellite no longer in view stays listed.
    void setKeepAfterLostMs(qint64 ms) { keepMs_ = ms; }

    static QString label(const SatelliteRow &row);

private:
    static quint64 key(SatelliteRef s, int signal) {
        return (quint64(quint8(s.system)) << 40) | (quint64(quint32(s.prn)) << 8) | quint8(signal);
    }
    static quint64 trackKey(SatelliteRef s) { return key(s, 0); }

    std::vector<SatelliteRow> rows_;
    QHash<quint64, int> index_; // key → row
    QHash<quint64, std::deque<TrackPoint>> tracks_;
    qint64 trackWindowMs_ = 30 * 60 * 1000;
    qint64 keepMs_ = 10 * 1000;
};

} // namespace gnss::ui
