#pragma once
// ConsoleModel: the lines received and sent, newest last, bounded. Lines arrive per sentence but
// are handed to views in batches (flush() on the session's timer), so a 20 Hz receiver does not
// repaint the console twenty times a second per line.
#include "models/value_format.h"

#include <QAbstractListModel>
#include <QByteArray>
#include <deque>
#include <vector>

namespace gnss::ui {

struct ConsoleLine {
    qint64 ms = 0;      // host time
    QByteArray text;    // the sentence, without line ending
    QByteArray address; // for filtering
    bool sent = false;  // a command we sent
    bool checksumBad = false;
    QString error; // why it could not be decoded (empty when it was, or when it is unknown)
    QString note;  // "unknown sentence": shown on hover, not as an error
};

class ConsoleModel : public QAbstractListModel {
    Q_OBJECT
public:
    enum Role { SentRole = Qt::UserRole + 1, ChecksumBadRole, ErrorRole, AddressRole, TimeRole };
    static constexpr int kMaxLines = 20000;

    explicit ConsoleModel(QObject *parent = nullptr);
    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;

    // Waits for the next flush. Lines past the cap would be dropped there anyway, so a burst
    // between two flushes (a busy event loop, a fast replay) keeps at most kMaxPending of them.
    void append(ConsoleLine line);
    void flush(); // moves pending lines into the model (one insert), drops the oldest past the cap
    static constexpr int kMaxPending = kMaxLines + kMaxLines / 4;
    std::size_t pendingLines() const { return pending_.size(); }
    // Room held for pending lines: given back after a burst (what the soak's heap shows).
    std::size_t pendingCapacity() const { return pending_.capacity(); }
    void clear();
    void setPaused(bool p) { paused_ = p; }
    // Arrival times in UTC or local time; the rows shown are rewritten.
    void setTimeZone(TimeZoneChoice zone) {
        zone_ = zone;
        if (!lines_.empty()) emit dataChanged(index(0), index(rowCount() - 1), {Qt::DisplayRole});
    }
    bool paused() const { return paused_; }

    // The last raw bytes received, for the hex view.
    void appendRaw(const QByteArray &bytes);
    const QByteArray &raw() const { return raw_; }

private:
    TimeZoneChoice zone_ = TimeZoneChoice::Utc;
    std::deque<ConsoleLine> lines_;
    std::vector<ConsoleLine> pending_;
    QByteArray raw_;
    bool paused_ = false;
};

} // namespace gnss::ui
