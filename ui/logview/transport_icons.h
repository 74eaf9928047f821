#pragma once
// The timeline's transport icons, drawn in the palette's text colour so they read in the light
// and the dark theme alike (the style's own media icons are dark grey on any background).
#include <QColor>
#include <QIcon>

namespace gnss::ui {

enum class TransportIcon {
    Start,
    PreviousEvent,
    StepBack,
    Play,
    Pause,
    StepForward,
    NextEvent,
    End
};

QIcon transportIcon(TransportIcon kind, const QColor &colour);

} // namespace gnss::ui
