#pragma once
// A watcher that records what a CorrectionSource says and delivers, for the tests to look at.
#include "corrections/correction_source.h"
#include "corrections/corrections_monitor.h"

#include <QList>
#include <QStringList>

namespace corrections_test {

// Everything a source says and delivers; what it delivers is also read by a corrections monitor.
struct SourceWatch {
    QByteArray data;
    gnss::corrections::CorrectionsMonitor monitor; // fed at time 0
    QStringList errors;
    QStringList statuses;
    QList<gnss::corrections::CorrectionSource::State> states;
    QList<int> waits; // retryInMs() each time the source starts waiting to retry

    explicit SourceWatch(gnss::corrections::CorrectionSource &s) {
        using gnss::corrections::CorrectionSource;
        QObject::connect(&s, &CorrectionSource::dataReceived, [this](const QByteArray &b) {
            data += b;
            monitor.feed(std::string_view(b.constData(), std::size_t(b.size())), 0);
        });
        QObject::connect(&s, &CorrectionSource::errorOccurred,
                         [this](const QString &e) { errors.append(e); });
        QObject::connect(&s, &CorrectionSource::statusChanged,
                         [this](const QString &t) { statuses.append(t); });
        QObject::connect(&s, &CorrectionSource::stateChanged,
                         [this, &s](CorrectionSource::State st) {
                             states.append(st);
                             if (st == CorrectionSource::State::WaitingToRetry)
                                 waits.append(s.retryInMs());
                         });
    }
    // Whether the monitor has seen a base station's position (1005) and its GPS and GLONASS
    // MSM4 (1074, 1084).
    bool sawBaseMessages() const {
        return monitor.messageType(1005, 0) && monitor.messageType(1074, 0) &&
               monitor.messageType(1084, 0);
    }
    // Whether any word the source said holds `secret`.
    bool said(const QString &secret) const {
        for (const QString &t : errors + statuses)
            if (t.contains(secret)) return true;
        return false;
    }
};

} // namespace corrections_test
