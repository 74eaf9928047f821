#pragma once
// Test helper: ends RTKLIB's str2str, which forgets a SIGTERM that comes while it starts: asked
// until it goes, killed after three seconds.
#include <QProcess>

namespace gnss::test {

inline void stopStr2str(QProcess &rtk) {
    for (int i = 0; i < 15 && rtk.state() != QProcess::NotRunning; ++i) {
        rtk.terminate();
        rtk.waitForFinished(200);
    }
    if (rtk.state() != QProcess::NotRunning) {
        rtk.kill();
        rtk.waitForFinished(3000);
    }
}

} // namespace gnss::test
