#pragma once
// TimeSeriesModel: the charts' data. One bounded buffer per series (satellites used, DOPs, fix
// type, mean SNR per constellation, standard deviations, baseline length, altitude, speed), one
// sample per navigation epoch, trimmed to a rolling window. Fed from ReceiverStateModel::updated;
// the chart reads it on its own timer, so the per-epoch cost is a few appends.
#include "models/value_format.h"
#include "state/receiver_state.h"

#include <QDateTime>
#include <QObject>
#include <QString>

#include <array>
#include <deque>
#include <optional>

namespace gnss::ui {

class ReceiverStateModel;

class TimeSeriesModel : public QObject {
    Q_OBJECT
public:
    enum Series : int {
        SatsUsed,
        Hdop,
        Pdop,
        FixKind, // FixType as its enum value (0 no fix ... 7 manual)
        SnrGps,
        SnrGlonass,
        SnrGalileo,
        SnrBeiDou,
        SnrQzss,
        SnrSbas,
        SnrNavIC,
        SdLat,
        SdLon,
        SdHeight,
        BaselineLength,
        AltitudeMsl,
        Speed,
        SeriesCount
    };
    // Series that share a unit share a chart.
    enum Group : int {
        Satellites,
        Dop,
        Fix,
        Snr,
        Deviation,
        Baseline,
        Altitude,
        SpeedGroup,
        GroupCount
    };

    struct Sample {
        qint64 msecs; // host time of the epoch, ms since 1970 UTC
        double value;
    };

    explicit TimeSeriesModel(QObject *parent = nullptr);

    // Follows a state model: one sample per updated(); a cleared model clears the series.
    void attach(ReceiverStateModel *model);

    // Rolling window in seconds (default 600 = 10 min).
    double windowSeconds() const { return windowMs_ / 1000.0; }
    void setWindowSeconds(double seconds);
    // Upper bound of samples kept per series whatever the window (default 36000: 1 h at 10 Hz).
    std::size_t capacity() const { return capacity_; }
    void setCapacity(std::size_t n);

    // One epoch's values; series without a value this epoch get no sample (a gap, never 0).
    void append(const ReceiverState &state, const QDateTime &hostTime);
    void clear();

    const std::deque<Sample> &samples(Series s) const { return series_[s]; }
    // Host time of the newest sample of any series (0 before the first).
    qint64 latestMsecs() const { return latestMs_; }
    // Bumped by every change: the chart redraws only when it moved.
    quint64 revision() const { return revision_; }

    // The value a series takes from one state (also what the tests check).
    static std::optional<double> valueOf(Series s, const ReceiverState &state);
    static QString key(Series s);   // stable name for settings: "satsUsed", "snr.GPS", ...
    static QString label(Series s); // translated legend text
    static Group group(Series s);
    // Translated chart title with its unit (lengths and speeds in `units`; samples stay SI).
    static QString groupTitle(Group g, UnitSystem units = UnitSystem::Metric);
    // The factor from a group's samples (SI) to what its chart shows in `units`.
    static double groupFactor(Group g, UnitSystem units);
    static std::optional<Series> fromKey(const QString &key);

private:
    void trim();

    std::array<std::deque<Sample>, SeriesCount> series_;
    qint64 windowMs_ = 600'000;
    std::size_t capacity_ = 36'000;
    qint64 latestMs_ = 0;
    quint64 revision_ = 0;
};

} // namespace gnss::ui
