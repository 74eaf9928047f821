#pragma once
// A watcher that records what a CorrectionSource says and delivers, for the tests to look at.
#include "correction_source.h"

#include <QList>
#include <QStringList>

namespace corrections_test {

// Everything a source says and delivers.
struct SourceWatch {
    QByteArray data;
    QStringList errors;
    QStringList statuses;
    QList<gnss::corrections::CorrectionSource::State> states;
    QList<int> waits; // retryInMs() each time the source starts waiting to retry

    explicit SourceWatch(gnss::corrections::CorrectionSource &s) {
        using gnss::corrections::CorrectionSource;
        QObject::connect(&s, &CorrectionSource::dataReceived,
                         [this](const QByteArray &b) { data += b; });
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
    // Whether any word the source said holds `secret`.
    bool said(const QString &secret) const {
        for (const QString &t : errors + statuses)
            if (t.contains(secret)) return true;
        return false;
    }
};

} // namespace corrections_test
