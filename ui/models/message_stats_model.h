#pragma once
// MessageStatsModel: per address count, rate, last seen and errors. Refreshed from the decoder's
// own counters on a timer, so counting costs nothing per sentence.
#include "core/stream_decoder.h"
#include "models/value_format.h"

#include <QAbstractTableModel>
#include <vector>

namespace gnss::ui {

class MessageStatsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Address,
        Count,
        Rate,
        LastSeen,
        ChecksumErrors,
        DecodeErrors,
        Unknown,
        ColumnCount
    };

    explicit MessageStatsModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation o, int role = Qt::DisplayRole) const override;

    // Takes the decoder's counters at host time nowMs; rates are measured over the last 5 s.
    void refresh(const std::vector<AddressStats> &stats, qint64 nowMs);
    void clear();
    // When each address was last seen: UTC or local time (Preferences).
    void setTimeZone(TimeZoneChoice zone);

    struct Row {
        QString address;
        quint64 count = 0, checksumErrors = 0, decodeErrors = 0, unknown = 0;
        double rateHz = 0;
        qint64 lastSeenMs = 0;
        std::vector<std::pair<qint64, quint64>> history; // (time, count) over the rate window
    };
    const std::vector<Row> &rows() const { return rows_; }

private:
    std::vector<Row> rows_;
    TimeZoneChoice zone_ = TimeZoneChoice::Utc;
};

} // namespace gnss::ui
