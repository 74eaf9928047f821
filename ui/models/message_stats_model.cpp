#include "models/message_stats_model.h"
#include "style/gnss_style.h"

#include <QColor>

namespace gnss::ui {
namespace {
constexpr qint64 kRateWindowMs = 5000;
}

MessageStatsModel::MessageStatsModel(QObject *parent) : QAbstractTableModel(parent) {}

int MessageStatsModel::rowCount(const QModelIndex &p) const {
    return p.isValid() ? 0 : int(rows_.size());
}
int MessageStatsModel::columnCount(const QModelIndex &p) const {
    return p.isValid() ? 0 : ColumnCount;
}

QVariant MessageStatsModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= int(rows_.size())) return {};
    const Row &r = rows_[size_t(index.row())];
    if (role == Qt::TextAlignmentRole && index.column() != Address)
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ForegroundRole && index.column() == ChecksumErrors && r.checksumErrors > 0)
        return style::errorColor();
    if (role == Qt::UserRole) { // sort key
        switch (index.column()) {
        case Address: return r.address;
        case Count: return r.count;
        case Rate: return r.rateHz;
        case LastSeen: return r.lastSeenMs;
        case ChecksumErrors: return r.checksumErrors;
        case DecodeErrors: return r.decodeErrors;
        case Unknown: return r.unknown;
        }
    }
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
    case Address: return r.address;
    case Count: return QString::number(r.count);
    case Rate: return QString::number(r.rateHz, 'f', r.rateHz < 10 ? 2 : 1);
    case LastSeen: return r.lastSeenMs ? fmt::hostTime(r.lastSeenMs, zone_) : fmt::dash();
    case ChecksumErrors: return QString::number(r.checksumErrors);
    case DecodeErrors: return QString::number(r.decodeErrors);
    case Unknown: return QString::number(r.unknown);
    }
    return {};
}

void MessageStatsModel::setTimeZone(TimeZoneChoice zone) {
    zone_ = zone;
    emit headerDataChanged(Qt::Horizontal, LastSeen, LastSeen);
    if (!rows_.empty()) emit dataChanged(index(0, LastSeen), index(rowCount() - 1, LastSeen));
}

QVariant MessageStatsModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Address: return tr("Address");
    case Count: return tr("Count");
    case Rate: return tr("Rate (Hz)");
    case LastSeen:
        return zone_ == TimeZoneChoice::Local ? tr("Last seen (local time)")
                                              : tr("Last seen (UTC)");
    case ChecksumErrors: return tr("Checksum errors");
    case DecodeErrors: return tr("Decode errors");
    case Unknown: return tr("Unknown");
    }
    return {};
}

void MessageStatsModel::refresh(const std::vector<AddressStats> &stats, qint64 nowMs) {
    const int firstNew = int(rows_.size());
    if (stats.size() > rows_.size()) {
        beginInsertRows({}, firstNew, int(stats.size()) - 1);
        for (std::size_t i = rows_.size(); i < stats.size(); ++i)
            rows_.push_back(Row{QString::fromStdString(stats[i].address)});
        endInsertRows();
    }
    for (std::size_t i = 0; i < stats.size(); ++i) {
        Row &r = rows_[i];
        const AddressStats &s = stats[i];
        if (s.sentences != r.count) r.lastSeenMs = nowMs;
        r.count = s.sentences;
        r.checksumErrors = s.checksumBad;
        r.decodeErrors = s.decodeErrors;
        r.unknown = s.unknown;
        r.history.emplace_back(nowMs, r.count);
        while (r.history.size() > 2 && nowMs - r.history[1].first >= kRateWindowMs)
            r.history.erase(r.history.begin());
        const auto &[t0, c0] = r.history.front();
        r.rateHz = nowMs > t0 ? double(r.count - c0) * 1000.0 / double(nowMs - t0) : 0.0;
    }
    if (!rows_.empty())
        emit dataChanged(index(0, 0), index(int(rows_.size()) - 1, ColumnCount - 1));
}

void MessageStatsModel::clear() {
    beginResetModel();
    rows_.clear();
    endResetModel();
}

} // namespace gnss::ui
