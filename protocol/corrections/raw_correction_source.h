#pragma once
// RawCorrectionSource: a source whose device carries RTCM and nothing else (a base's TCP port, a
// radio modem on a serial port): what it reads while receiving is delivered as it comes, with no
// framing to take off. Holds what the TCP and serial sources share: the read handler and the
// `closing_` flag (link/while_closing.h) their device's handlers check.
#include "corrections/correction_source.h"

#include <QIODevice>

namespace gnss::corrections {

class RawCorrectionSource : public CorrectionSource {
    Q_OBJECT
protected:
    explicit RawCorrectionSource(QObject *parent = nullptr) : CorrectionSource(parent) {}

    // Delivers what `device` reads while receiving; the first bytes say so on the status line.
    // The subclass's constructor calls it once, for its own device.
    void deliverReadsOf(QIODevice &device);
    // Whether a report of the device counts: not while it is closed on purpose, nor when no
    // connection is being made or used.
    bool listening() const { return !closing_ && isActive(); }

    bool closing_ = false; // set while the device is closed on purpose
};

} // namespace gnss::corrections
