#pragma once
// The dark theme: a Fusion palette in dark greys with the Okabe-Ito blue for selection, and
// disabled controls that still look disabled.
#include <QPalette>

namespace gnss::style {

QPalette darkPalette();

} // namespace gnss::style
