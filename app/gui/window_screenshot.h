#pragma once
// The picture --screenshot saves: the window as painted, at the screen's device pixel ratio, as
// a PNG of 256 colours compressed as far as Qt goes (a 1280x800 window in about 60 kB). The PNG
// says what it shows in text chunks, so a test (or a
// person) can check it without guessing: "Software" (program and version), "DevicePixelRatio",
// and one "View <dock>" = "x,y,width,height" per dock shown, in the window's logical pixels.
#include <QString>

class QMainWindow;

namespace gnss::app {

// False with `error` set when the file cannot be written.
bool saveWindowScreenshot(QMainWindow &window, const QString &path, QString *error = nullptr);

} // namespace gnss::app
