#include "models/satellite_model.h"

#include "style/gnss_style.h"

#include <QColor>
#include <QDateTime>
#include <algorithm>

namespace gnss::ui {
namespace {
constexpr qint64 kTrackStepMs = 10 * 1000; // one track point per satellite every 10 s
}

SatelliteModel::SatelliteModel(QObject *parent) : QAbstractTableModel(parent) {}

int SatelliteModel::rowCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int SatelliteModel::columnCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString SatelliteModel::label(const SatelliteRow &row) {
    QString l = QString::fromStdString(satelliteLabel(row.sat));
    const auto sig = signalName(row.sat.system, row.signalId);
    if (!sig.empty() && row.signalId > 1)
        l += ' ' + QString::fromLatin1(sig.data(), int(sig.size()));
    return l;
}

QVariant SatelliteModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= int(rows_.size())) return {};
    const SatelliteRow &r = rows_[size_t(index.row())];
    auto opt = [](const std::optional<int> &v) { return v ? QVariant(*v) : QVariant(); };
    switch (role) {
    case ConstellationRole: return int(r.sat.system);
    case PrnRole: return r.sat.prn;
    case SignalRole: return r.signalId;
    case ElevationRole: return opt(r.elevation);
    case AzimuthRole: return opt(r.azimuth);
    case SnrRole: return opt(r.snr);
    case UsedRole: return r.used;
    case InViewRole: return r.inView;
    case LabelRole: return label(r);
    case Qt::ForegroundRole:
        if (index.column() == System) return style::constellationColor(r.sat.system);
        return r.inView ? QVariant() : QVariant(style::mutedColor());
    case Qt::DisplayRole: {
        const QString dash = QStringLiteral("—");
        auto show = [&](const std::optional<int> &v) { return v ? QString::number(*v) : dash; };
        switch (index.column()) {
        case System: return style::constellationName(r.sat.system);
        case Prn: return label(r);
        case Signal: {
            const auto s = signalName(r.sat.system, r.signalId);
            return s.empty() ? dash : QString::fromLatin1(s.data(), int(s.size()));
        }
        case Elevation: return show(r.elevation);
        case Azimuth: return show(r.azimuth);
        case Snr: return show(r.snr);
        case Used: return r.used ? tr("yes") : tr("no");
        case LastSeen:
            return QDateTime::fromMSecsSinceEpoch(r.lastSeenMs, Qt::UTC).toString("hh:mm:ss");
        }
        return {};
    }
    case Qt::TextAlignmentRole:
        return index.column() >= Elevation ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                                           : QVariant();
    default: return {};
    }
}

QVariant SatelliteModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case System: return tr("System");
    case Prn: return tr("Satellite");
    case Signal: return tr("Signal");
    case Elevation: return tr("Elev. (°)");
    case Azimuth: return tr("Azim. (°)");
    case Snr: return tr("SNR (dB-Hz)");
    case Used: return tr("Used");
    case LastSeen: return tr("Last seen (UTC)");
    }
    return {};
}

const std::deque<TrackPoint> *SatelliteModel::track(const SatelliteRow &row) const {
    auto it = tracks_.constFind(trackKey(row.sat));
    return it == tracks_.constEnd() ? nullptr : &*it;
}

void SatelliteModel::update(const Epoch &epoch, qint64 nowMs) {
    for (auto &r : rows_) r.inView = false;
    bool structural = false;
    for (const SatelliteInView &s : epoch.satellites) {
        const quint64 k = key(s.sat, s.signalId);
        auto it = index_.find(k);
        if (it == index_.end()) {
            structural = true;
            index_.insert(k, int(rows_.size()));
            rows_.push_back(SatelliteRow{s.sat, s.signalId});
            it = index_.find(k);
        }
        SatelliteRow &r = rows_[size_t(*it)];
        r.elevation = s.elevation;
        r.azimuth = s.azimuth;
        r.snr = s.snr;
        r.used = s.used;
        r.inView = true;
        r.lastSeenMs = nowMs;
        if (s.elevation && s.azimuth && *s.elevation >= 0) {
            auto &t = tracks_[trackKey(s.sat)];
            if (t.empty() || nowMs - t.back().ms >= kTrackStepMs)
                t.push_back({nowMs, float(*s.azimuth), float(*s.elevation)});
        }
    }
    // Forget satellites out of view for too long, and old track points.
    const auto before = rows_.size();
    rows_.erase(std::remove_if(rows_.begin(), rows_.end(),
                               [&](const SatelliteRow &r) {
                                   return !r.inView && nowMs - r.lastSeenMs > keepMs_;
                               }),
                rows_.end());
    structural |= rows_.size() != before;
    for (auto it = tracks_.begin(); it != tracks_.end();) {
        while (!it->empty() && nowMs - it->front().ms > trackWindowMs_) it->pop_front();
        it = it->empty() ? tracks_.erase(it) : std::next(it);
    }
    if (structural) {
        // Keep a stable order: by constellation, then PRN, then signal.
        beginResetModel();
        std::sort(rows_.begin(), rows_.end(), [](const SatelliteRow &a, const SatelliteRow &b) {
            if (a.sat.system != b.sat.system) return a.sat.system < b.sat.system;
            if (a.sat.prn != b.sat.prn) return a.sat.prn < b.sat.prn;
            return a.signalId < b.signalId;
        });
        index_.clear();
        for (int i = 0; i < int(rows_.size()); ++i)
            index_.insert(key(rows_[size_t(i)].sat, rows_[size_t(i)].signalId), i);
        endResetModel();
    } else if (!rows_.empty()) {
        emit dataChanged(index(0, 0), index(int(rows_.size()) - 1, ColumnCount - 1));
    }
}

void SatelliteModel::clear() {
    beginResetModel();
    rows_.clear();
    index_.clear();
    tracks_.clear();
    endResetModel();
}

} // namespace gnss::ui
