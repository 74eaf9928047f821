#pragma once
// Runs a detector of the link layer (BaudDetector, VendorDetector: start(), then finished) to its
// end in the test's event loop.
#include <QSignalSpy>

namespace gnss::test {

// Starts `detector` and waits up to `ms` for it to finish; whether it did.
template <class Detector> bool runToFinish(Detector &detector, int ms) {
    QSignalSpy finished(&detector, &Detector::finished);
    detector.start();
    return finished.wait(ms);
}

} // namespace gnss::test
