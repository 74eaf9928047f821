// Golden tests over real receiver captures (../shared/corpus/gpsd): every sentence gpsd turned
// into a position must give us the same latitude and longitude, and the satellites gpsd saw must
// be the satellites we see (same constellation and PRN, same elevation and azimuth). Skipped
// cleanly when the corpus is absent.
#include "builtin/dialects.h"
#include "core/stream_decoder.h"
#include "nmea/nmea_messages.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTest>
#include <cmath>

using namespace gnss;

namespace {

QString corpusDir() {
    return QStringLiteral(GNSS_SHARED_DIR "/corpus/gpsd");
}

// gpsd's gnssid → our constellation.
Constellation fromGnssId(int g) {
    switch (g) {
    case 0: return Constellation::Gps;
    case 1: return Constellation::Sbas;
    case 2: return Constellation::Galileo;
    case 3: return Constellation::BeiDou;
    case 5: return Constellation::Qzss;
    case 6: return Constellation::Glonass;
    case 7: return Constellation::NavIC;
    default: return Constellation::Unknown;
    }
}

// Captures where gpsd sees satellites through sentences outside our dialects, and why.
struct Exception {
    const char *log;
    Constellation system;
    const char *reason;
};
constexpr Exception kExceptions[] = {
        {"quectel-eg25-g.log", Constellation::BeiDou,
         "BeiDou comes only in Quectel's proprietary $PQGSV, not a dialect we decode"},
};

struct Position {
    double lat, lon;
};

} // namespace

class TstCorpusGolden : public QObject {
    Q_OBJECT
private slots:
    void captureMatchesGpsd_data() {
        QTest::addColumn<QString>("log");
        const QDir dir(corpusDir());
        if (!dir.exists()) QSKIP("../shared/corpus not present");
        const auto logs = dir.entryList({"*.log"}, QDir::Files, QDir::Name);
        for (const auto &l : logs)
            if (QFile::exists(dir.filePath(l + ".chk")))
                QTest::newRow(qPrintable(l)) << dir.filePath(l);
    }

    void captureMatchesGpsd() {
        QFETCH(QString, log);
        QFile chk(log + ".chk");
        QVERIFY(chk.open(QIODevice::ReadOnly));
        const DialectRegistry reg = makeBuiltinRegistry();
        StreamDecoder dec(reg, {.lenient = false});

        std::optional<Position> ours; // position decoded from the last sentence
        int positionsCompared = 0;
        QSet<QString> ourSky, gpsdSky;
        QString mismatches;
        while (!chk.atEnd()) {
            const QByteArray line = chk.readLine().trimmed();
            if (line.startsWith('$') || line.startsWith('!')) {
                ours.reset();
                dec.decodeLine(line.toStdString(), [&](const SentenceEvent &ev) {
                    if (!ev.message) return;
                    const Message &m = *ev.message;
                    std::optional<double> lat, lon;
                    if (auto *g = message_cast<nmea::Gga>(m)) lat = g->lat, lon = g->lon;
                    if (auto *r = message_cast<nmea::Rmc>(m)) lat = r->lat, lon = r->lon;
                    if (auto *l = message_cast<nmea::Gll>(m)) lat = l->lat, lon = l->lon;
                    if (auto *n = message_cast<nmea::Gns>(m)) lat = n->lat, lon = n->lon;
                    if (lat && lon) ours = Position{*lat, *lon};
                    if (auto *v = message_cast<nmea::Gsv>(m)) {
                        for (std::size_t i = 0; i < v->satelliteCount; ++i) {
                            const auto &s = v->satellites[i];
                            if (!s.elevation || !s.azimuth) continue;
                            ourSky.insert(
                                    QString("%1:%2:%3:%4")
                                            .arg(QString::fromLatin1(toString(s.sat.system).data()))
                                            .arg(s.sat.prn)
                                            .arg(*s.elevation)
                                            .arg(*s.azimuth));
                        }
                    }
                });
                continue;
            }
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            if (o["class"] == "TPV" && o.contains("lat") && ours) {
                ++positionsCompared;
                if (std::abs(o["lat"].toDouble() - ours->lat) > 1e-6 ||
                    std::abs(o["lon"].toDouble() - ours->lon) > 1e-6)
                    mismatches += QString(" lat/lon %1,%2 vs gpsd %3,%4;")
                                          .arg(ours->lat, 0, 'f', 9)
                                          .arg(ours->lon, 0, 'f', 9)
                                          .arg(o["lat"].toDouble(), 0, 'f', 9)
                                          .arg(o["lon"].toDouble(), 0, 'f', 9);
            }
            if (o["class"] == "SKY") {
                for (const auto &sv : o["satellites"].toArray()) {
                    const QJsonObject s = sv.toObject();
                    if (!s.contains("el") || !s.contains("az") || !s.contains("gnssid")) continue;
                    const Constellation c = fromGnssId(s["gnssid"].toInt());
                    if (c == Constellation::Unknown) continue;
                    bool excepted = false;
                    for (const auto &e : kExceptions)
                        excepted |= QFileInfo(log).fileName() == e.log && e.system == c;
                    if (excepted) continue;
                    gpsdSky.insert(QString("%1:%2:%3:%4")
                                           .arg(QString::fromLatin1(toString(c).data()))
                                           .arg(s["svid"].toInt())
                                           .arg(int(s["el"].toDouble()))
                                           .arg(int(s["az"].toDouble())));
                }
            }
        }
        QVERIFY2(mismatches.isEmpty(), qPrintable(mismatches.left(600)));
        // Satellites gpsd reports must be among ours (gpsd drops some; we may see more).
        const QSet<QString> missing = gpsdSky - ourSky;
        const double coverage =
                gpsdSky.isEmpty() ? 1.0 : 1.0 - double(missing.size()) / gpsdSky.size();
        QVERIFY2(coverage >= 0.95,
                 qPrintable(QString("%1 of %2 gpsd satellites not seen, e.g. %3")
                                    .arg(missing.size())
                                    .arg(gpsdSky.size())
                                    .arg(QStringList(missing.values().mid(0, 5)).join(' '))));
        qInfo("%s: %d positions compared, %lld sky entries", qPrintable(QFileInfo(log).fileName()),
              positionsCompared, static_cast<long long>(gpsdSky.size()));
    }
};

QTEST_GUILESS_MAIN(TstCorpusGolden)
#include "tst_corpus_golden.moc"
