#pragma once
// GpsdReader: splits what gpsd sends a client in raw mode (?WATCH={"raw":1}) into the receiver's
// own sentences and gpsd's JSON reports. gpsd writes whole lines: its reports are JSON objects
// ({"class":"VERSION",...}), the receiver's NMEA and AIVDM sentences come through as the device
// sent them ($... or !...), and binary packets (RTCM, a vendor's binary protocol) as hex dumps.
//
// Only the sentences are receiver data. gpsd's reports are returned separately (the transport
// reads VERSION, DEVICES, WATCH and ERROR from them). The hex dumps are dropped and counted:
// they are gpsd's rendering of packets it framed, not the bytes on the wire, and nothing above
// the link decodes vendor binary (the decoder would only count it as skipped).
#include <QByteArray>
#include <QJsonObject>

#include <vector>

namespace gnss::link {

class GpsdReader {
public:
    // Feeds bytes as they arrive (any chunking); returns the receiver's complete sentences among
    // them, each ended by CR LF, and appends gpsd's reports to `reports`.
    QByteArray feed(const QByteArray &bytes, std::vector<QJsonObject> &reports);
    // Forgets a partly received line (a new connection starts clean).
    void reset() { partial_.clear(); }

    // Lines that were neither a sentence nor a report: hex dumps of binary packets, JSON that
    // did not parse, lines too long to be either.
    quint64 linesDropped() const { return dropped_; }

    // Longest line kept waiting for its end; gpsd's longest reports are a few kB.
    static constexpr qsizetype kMaxLine = 64 * 1024;

private:
    QByteArray partial_;
    quint64 dropped_ = 0;
    bool skipping_ = false; // inside a line that grew past kMaxLine: dropped up to its end
};

} // namespace gnss::link
