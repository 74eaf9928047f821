#pragma once
// The view conventions of UI.md in one place: constellation colours (Okabe-Ito) and marker
// shapes, fix-type badge words and colours. Change one here and every view follows.
#include "core/fix_type.h"
#include "core/satellite.h"

#include <QColor>
#include <QString>

namespace gnss::style {

enum class Marker { Circle, Square, Diamond, TriangleUp, Pentagon, TriangleDown, Star };

QColor constellationColor(Constellation c);
Marker constellationMarker(Constellation c);

// Badge text (translated) and colour for a fix type.
QString fixTypeLabel(FixType f);
QColor fixTypeColor(FixType f);

// Errors and warnings in text, ticks and badges (checksum errors, REC, refused input).
QColor errorColor();

} // namespace gnss::style
