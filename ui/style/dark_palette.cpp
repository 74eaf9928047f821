#include "style/dark_palette.h"

#include "style/gnss_style.h"

namespace gnss::style {

QPalette darkPalette() {
    QPalette p;
    const QColor text(0xe6, 0xe6, 0xe6);
    p.setColor(QPalette::Window, QColor(0x2b, 0x2d, 0x30));
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, QColor(0x1e, 0x1f, 0x22));
    p.setColor(QPalette::AlternateBase, QColor(0x26, 0x28, 0x2b));
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, QColor(0x35, 0x37, 0x3b));
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::Highlight, lineColor(LineTone::Blue));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::Mid, QColor(0x6b, 0x6f, 0x75));
    p.setColor(QPalette::Midlight, QColor(0x45, 0x48, 0x4d));
    p.setColor(QPalette::PlaceholderText, QColor(0x9a, 0x9e, 0xa5));
    // Disabled controls (the source box while connected) must look disabled in the dark too.
    const QColor disabled(0x7a, 0x7e, 0x85);
    for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, disabled);
    p.setColor(QPalette::Disabled, QPalette::Button, QColor(0x2f, 0x31, 0x35));
    return p;
}

} // namespace gnss::style
