#pragma once
// The application icon (resources/icons/gnss-workbench.svg), painted at the sizes a window
// manager asks for, so no SVG plugin is needed.
#include <QIcon>
#include <QPixmap>

namespace gnss::style {

// The icon drawn at size x size pixels (also the package's hicolor PNGs: packaging/).
QPixmap appIconPixmap(int size);
QIcon appIcon();

} // namespace gnss::style
