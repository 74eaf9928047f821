#include "value_format.h"

#include <QCoreApplication>
#include <cmath>

namespace gnss::ui::fmt {

QString dash() {
    return QStringLiteral("—");
}

QString number(const std::optional<double> &v, int decimals, const QString &unit) {
    if (!v || !std::isfinite(*v)) return dash();
    QString s = QString::number(*v, 'f', decimals);
    return unit.isEmpty() ? s : s + ' ' + unit;
}

QString integer(const std::optional<int> &v, const QString &unit) {
    if (!v) return dash();
    return unit.isEmpty() ? QString::number(*v) : QString::number(*v) + ' ' + unit;
}

namespace {
QString coordinate(const std::optional<double> &deg, bool dms, const char *pos, const char *neg) {
    if (!deg) return dash();
    const double a = std::abs(*deg);
    const QString hemi = QCoreApplication::translate("Hemisphere", *deg < 0 ? neg : pos);
    if (!dms) return QStringLiteral("%1° %2").arg(a, 0, 'f', 8).arg(hemi);
    int d = int(a);
    int m = int((a - d) * 60);
    double s = ((a - d) * 60 - m) * 60;
    if (s >= 59.99995) { // carry what rounding to 4 decimals would show as 60
        s = 0;
        if (++m == 60) m = 0, ++d;
    }
    return QStringLiteral("%1° %2′ %3″ %4")
            .arg(d)
            .arg(m, 2, 10, QChar('0'))
            .arg(s, 7, 'f', 4, QChar('0'))
            .arg(hemi);
}
} // namespace

QString latitude(const std::optional<double> &deg, bool dms) {
    return coordinate(deg, dms, QT_TRANSLATE_NOOP("Hemisphere", "N"),
                      QT_TRANSLATE_NOOP("Hemisphere", "S"));
}

QString longitude(const std::optional<double> &deg, bool dms) {
    return coordinate(deg, dms, QT_TRANSLATE_NOOP("Hemisphere", "E"),
                      QT_TRANSLATE_NOOP("Hemisphere", "W"));
}

} // namespace gnss::ui::fmt
