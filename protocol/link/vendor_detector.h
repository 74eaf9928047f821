#pragma once
// VendorDetector: which receiver family is on the line, and when it says so, its model and
// firmware. Passive first: the proprietary sentences in its output name the dialect (detected
// by the link's own decoder, which this listens to). Then active: each dialect's probe (PNVGVER,
// $GPSGG,RQUERY, PNMRX600...) with a short timeout, the answer matched by that dialect's reply
// rule, and model and firmware read by that dialect's own updateState (nothing here knows a
// vendor's fields). A known dialect is still probed once, for model and firmware.
#include "core/dialect_registry.h"
#include "core/sentence.h"
#include "core/stream_decoder.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>

namespace gnss::link {

class SentenceStream;
class Transport;

struct VendorIdentity {
    bool found = false;
    QString dialect;     // "nvs"; "nmea" when only standard sentences were seen
    QString dialectName; // "NVS NV08C-RTK"
    QString model;       // as the receiver reports it, empty when it does not
    QString firmware;
    QString method;    // "passive" (from the output) or "active" (answered a probe)
    QString reply;     // the sentence that identified it
    QString replyJson; // the reply decoded, as JSON (empty when not decoded)
    QString error;     // why nothing was found
};

class VendorDetector : public QObject {
    Q_OBJECT
public:
    // Listens to `stream` (the link's decoder) and writes probes to its transport.
    explicit VendorDetector(SentenceStream *stream, QObject *parent = nullptr);
    ~VendorDetector() override;

    void setPassiveMs(int ms) { passiveMs_ = ms; }
    void setProbeTimeoutMs(int ms) { probeTimeoutMs_ = ms; }
    // Only listen (a replay, or a receiver that must not be written to).
    void setActive(bool active) { active_ = active; }

    void start();
    const VendorIdentity &result() const { return result_; }

signals:
    void finished(const gnss::link::VendorIdentity &identity);

private:
    void onEvent(const SentenceEvent &ev);
    void passiveDone();
    void probeNext();
    void done();

    QPointer<SentenceStream> stream_;
    QPointer<Transport> transport_;
    int passiveMs_ = 1500;
    int probeTimeoutMs_ = 800;
    bool active_ = true;
    bool running_ = false;
    bool sawValid_ = false;
    std::vector<const Dialect *> toProbe_;
    const Dialect *probing_ = nullptr;
    std::string probeLine_;
    Sentence probeSentence_;
    ReplyProgress progress_;
    const Dialect *passive_ = nullptr;
    VendorIdentity result_;
    QTimer timer_;
    QMetaObject::Connection eventConnection_;
};

} // namespace gnss::link
