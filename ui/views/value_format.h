#pragma once
// Number formatting shared by the panels (UI.md "Numbers and units"): "—" for a value the
// receiver has not sent, hemispheres instead of signs, units always said.
#include <QString>
#include <optional>

namespace gnss::ui::fmt {

QString dash();
QString number(const std::optional<double> &v, int decimals, const QString &unit = {});
QString integer(const std::optional<int> &v, const QString &unit = {});
// 55.84338247° N  |  55° 50′ 36.1769″ N
QString latitude(const std::optional<double> &deg, bool dms);
QString longitude(const std::optional<double> &deg, bool dms);

} // namespace gnss::ui::fmt
