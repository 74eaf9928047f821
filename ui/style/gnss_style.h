#pragma once
// The view conventions in one place: constellation colours (Okabe-Ito) and marker
// shapes, fix-type badge words and colours. Change one here and every view follows.
// Nothing depends on colour alone: each constellation has its own marker shape too.
#include "core/fix_type.h"
#include "core/satellite.h"

#include <QColor>
#include <QString>

namespace gnss::style {

enum class Marker { Circle, Square, Diamond, TriangleUp, Pentagon, TriangleDown, Star };

QColor constellationColor(Constellation c);
Marker constellationMarker(Constellation c);
// A constellation's name as the views show it: the systems' own names ("GPS", "GLONASS"), and
// for a satellite whose system the receiver's numbering does not tell, a translated word.
QString constellationName(Constellation c);

// Badge text (translated) and colour for a fix type.
QString fixTypeLabel(FixType f);
QColor fixTypeColor(FixType f);

// Errors and warnings in text, ticks and badges (checksum errors, REC, refused input).
QColor errorColor();
// A state that is as it should be (a check passed, no jamming).
QColor okColor();
// A value to look at twice (out of the receiver's range, not applied yet).
QColor cautionColor();
// What is listed but not current, in text (a satellite no longer in view).
QColor mutedColor();
// What the user sent, and the lines of a chart that are not a constellation's (Okabe-Ito).
QColor sentColor();
enum class LineTone { Blue, Vermillion, BluishGreen, ReddishPurple };
QColor lineColor(LineTone t);
// For widgets coloured by a style sheet: "color: #rrggbb;".
QString textColorCss(const QColor &c);
// Text on a coloured badge (the fix badges of the status bar, the Fix and RTK docks).
QColor badgeTextColor();
// A badge's style sheet declarations: badge text on `background`, corners rounded by `radius`
// px, `padding` as CSS ("1px 6px").
QString badgeCss(const QColor &background, int radius, const char *padding);

} // namespace gnss::style
