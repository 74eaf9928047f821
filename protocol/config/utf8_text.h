#pragma once
// A schema's or a receiver's UTF-8 text (std::string_view) as a QString: one helper for the
// settings layers and the forms built on them.
#include <QString>

#include <string_view>

namespace gnss::config {

inline QString qs(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

} // namespace gnss::config
