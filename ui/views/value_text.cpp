#include "value_text.h"

#include <QChar>

#include <cmath>

namespace gnss::ui::text {

QString dash() { return QString(QChar(0x2014)); }

QString number(std::optional<double> v, int decimals, const QString &unit) {
    if (!v || !std::isfinite(*v)) return dash();
    QString s = QString::number(*v, 'f', decimals);
    if (!unit.isEmpty()) s += QLatin1Char(' ') + unit;
    return s;
}

QString integer(std::optional<std::int64_t> v, const QString &unit) {
    if (!v) return dash();
    QString s = QString::number(*v);
    if (!unit.isEmpty()) s += QLatin1Char(' ') + unit;
    return s;
}

static QString hemisphere(std::optional<double> deg, int decimals, QChar pos, QChar neg) {
    if (!deg || !std::isfinite(*deg)) return dash();
    return QString::number(std::fabs(*deg), 'f', decimals) + QChar(0x00B0) + QLatin1Char(' ') +
           (*deg < 0 ? neg : pos);
}

QString latitude(std::optional<double> deg, int decimals) {
    return hemisphere(deg, decimals, QLatin1Char('N'), QLatin1Char('S'));
}

QString longitude(std::optional<double> deg, int decimals) {
    return hemisphere(deg, decimals, QLatin1Char('E'), QLatin1Char('W'));
}

QString utcTime(const std::optional<TimeOfDay> &t) {
    if (!t) return dash();
    return QString::fromStdString(t->toString(3));
}

} // namespace gnss::ui::text
