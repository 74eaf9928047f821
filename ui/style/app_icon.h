#pragma once
// The application icon (resources/icons/gnss-workbench.svg), painted at the sizes a window
// manager asks for, so no SVG plugin is needed.
#include <QIcon>

namespace gnss::style {

QIcon appIcon();

} // namespace gnss::style
