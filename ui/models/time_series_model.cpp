#include "models/time_series_model.h"

#include "models/receiver_state_model.h"

#include <algorithm>
#include <iterator>

namespace gnss::ui {

namespace {

constexpr double kKnotsToMs = 1852.0 / 3600.0;

Constellation snrConstellation(TimeSeriesModel::Series s) {
    switch (s) {
    case TimeSeriesModel::SnrGps: return Constellation::Gps;
    case TimeSeriesModel::SnrGlonass: return Constellation::Glonass;
    case TimeSeriesModel::SnrGalileo: return Constellation::Galileo;
    case TimeSeriesModel::SnrBeiDou: return Constellation::BeiDou;
    case TimeSeriesModel::SnrQzss: return Constellation::Qzss;
    case TimeSeriesModel::SnrSbas: return Constellation::Sbas;
    case TimeSeriesModel::SnrNavIC: return Constellation::NavIC;
    default: return Constellation::Unknown;
    }
}

// Each series' settings key, label and chart, in the order of Series; the SNR series have no
// key or label here: theirs are made from their constellation's name.
struct SeriesText {
    const char *key;
    const char *label;
    TimeSeriesModel::Group group;
};
using TS = TimeSeriesModel;
constexpr SeriesText kSnr{nullptr, nullptr, TS::Snr};
constexpr SeriesText kSeriesTexts[] = {
        {"satsUsed", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Satellites used"),
         TS::Satellites},
        {"hdop", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "HDOP"), TS::Dop},
        {"pdop", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "PDOP"), TS::Dop},
        {"fixType", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Fix type"), TS::Fix},
        kSnr, // GPS
        kSnr, // GLONASS
        kSnr, // Galileo
        kSnr, // BeiDou
        kSnr, // QZSS
        kSnr, // SBAS
        kSnr, // NavIC
        {"sdLat", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Std. dev. latitude"),
         TS::Deviation},
        {"sdLon", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Std. dev. longitude"),
         TS::Deviation},
        {"sdHeight", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Std. dev. height"),
         TS::Deviation},
        {"baselineLength", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Baseline length"),
         TS::Baseline},
        {"altitudeMsl", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Altitude above sea level"),
         TS::Altitude},
        {"speed", QT_TRANSLATE_NOOP("gnss::ui::TimeSeriesModel", "Speed"), TS::SpeedGroup},
};
static_assert(std::size(kSeriesTexts) == TS::SeriesCount);

} // namespace

TimeSeriesModel::TimeSeriesModel(QObject *parent) : QObject(parent) {}

void TimeSeriesModel::attach(ReceiverStateModel *model) {
    connect(model, &ReceiverStateModel::updated, this, [this, model] {
        if (model->epochCount() == 0)
            clear();
        else
            append(model->state(), model->lastEpochTime());
    });
}

void TimeSeriesModel::setWindowSeconds(double seconds) {
    windowMs_ = std::max<qint64>(1000, static_cast<qint64>(seconds * 1000.0));
    trim();
    ++revision_;
}

void TimeSeriesModel::setCapacity(std::size_t n) {
    capacity_ = std::max<std::size_t>(2, n);
    trim();
    ++revision_;
}

void TimeSeriesModel::append(const ReceiverState &state, const QDateTime &hostTime) {
    const qint64 t = hostTime.isValid() ? hostTime.toMSecsSinceEpoch() : latestMs_;
    // A host clock stepping back would break the time order the trimming relies on.
    latestMs_ = std::max(latestMs_, t);
    for (int i = 0; i < SeriesCount; ++i) {
        const auto s = static_cast<Series>(i);
        if (auto v = valueOf(s, state)) series_[i].push_back({latestMs_, *v});
    }
    trim();
    ++revision_;
}

void TimeSeriesModel::clear() {
    for (auto &s : series_) s.clear();
    latestMs_ = 0;
    ++revision_;
}

void TimeSeriesModel::trim() {
    const qint64 oldest = latestMs_ - windowMs_;
    for (auto &s : series_) {
        while (!s.empty() && s.front().msecs < oldest) s.pop_front();
        while (s.size() > capacity_) s.pop_front();
    }
}

std::optional<double> TimeSeriesModel::valueOf(Series s, const ReceiverState &st) {
    const Epoch &e = st.epoch;
    switch (s) {
    case SatsUsed:
        if (e.satsUsed) return *e.satsUsed;
        return std::nullopt;
    case Hdop: return e.hdop ? e.hdop : st.rtk.hdop;
    case Pdop: return e.pdop ? e.pdop : st.rtk.pdop;
    case FixKind: return static_cast<double>(static_cast<int>(e.fix));
    case SnrGps:
    case SnrGlonass:
    case SnrGalileo:
    case SnrBeiDou:
    case SnrQzss:
    case SnrSbas:
    case SnrNavIC: {
        const Constellation c = snrConstellation(s);
        double sum = 0;
        int n = 0;
        for (const auto &sat : e.satellites) {
            if (sat.sat.system == c && sat.snr) {
                sum += *sat.snr;
                ++n;
            }
        }
        if (n == 0) return std::nullopt;
        return sum / n;
    }
    case SdLat: return st.rtk.sdLat;
    case SdLon: return st.rtk.sdLon;
    case SdHeight: return st.rtk.sdHeight;
    case BaselineLength: return st.rtk.baseToRover.length;
    case AltitudeMsl: return e.altMsl;
    case Speed:
        if (e.sogKnots) return *e.sogKnots * kKnotsToMs;
        return std::nullopt;
    case SeriesCount: break;
    }
    return std::nullopt;
}

QString TimeSeriesModel::key(Series s) {
    if (s < 0 || s >= SeriesCount) return {};
    if (const char *k = kSeriesTexts[s].key) return QString::fromLatin1(k);
    const auto name = toString(snrConstellation(s));
    return QStringLiteral("snr.") + QString::fromLatin1(name.data(), name.size());
}

std::optional<TimeSeriesModel::Series> TimeSeriesModel::fromKey(const QString &k) {
    for (int i = 0; i < SeriesCount; ++i)
        if (key(static_cast<Series>(i)) == k) return static_cast<Series>(i);
    return std::nullopt;
}

QString TimeSeriesModel::label(Series s) {
    if (s < 0 || s >= SeriesCount) return {};
    if (const char *l = kSeriesTexts[s].label) return tr(l);
    const auto name = toString(snrConstellation(s));
    return tr("Mean SNR %1").arg(QString::fromLatin1(name.data(), name.size()));
}

TimeSeriesModel::Group TimeSeriesModel::group(Series s) {
    return s >= 0 && s < SeriesCount ? kSeriesTexts[s].group : Snr;
}

QString TimeSeriesModel::groupTitle(Group g, UnitSystem units) {
    const QString length = fmt::lengthUnit(units);
    switch (g) {
    case Satellites: return tr("Satellites used");
    case Dop: return tr("DOP");
    case Fix: return tr("Fix type");
    case Snr: return tr("Mean SNR (dB-Hz)");
    case Deviation: return tr("Standard deviation (%1)").arg(length);
    case Baseline: return tr("Baseline length (%1)").arg(length);
    case Altitude: return tr("Altitude above sea level (%1)").arg(length);
    case SpeedGroup: return tr("Speed (%1)").arg(fmt::speedUnit(units));
    case GroupCount: break;
    }
    return {};
}

double TimeSeriesModel::groupFactor(Group g, UnitSystem units) {
    switch (g) {
    case Deviation:
    case Baseline:
    case Altitude: return fmt::lengthFactor(units);
    case SpeedGroup: return fmt::speedFactor(units);
    default: return 1.0;
    }
}

} // namespace gnss::ui
