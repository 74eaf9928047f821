// The user's site list on disk and the site files: reading (JSON through Qt), atomic writing
// (site_store.h).
#include "sites/site_store.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>

#include <algorithm>

namespace gnss::sites {
namespace {

enum class FileKind { Json, Csv, Other };

FileKind siteFileKind(const QString &path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("json")  ? FileKind::Json
           : suffix == QLatin1String("csv") ? FileKind::Csv
                                            : FileKind::Other;
}

} // namespace

QString SiteStore::defaultDirectory() {
    const QByteArray set = qgetenv(kDirectoryVariable);
    if (!set.isEmpty()) return QString::fromLocal8Bit(set);
    // What AppDataLocation is for the GUI (organisation and application "GNSS Workbench"),
    // whatever this program calls itself.
    const QString name = QStringLiteral("GNSS Workbench");
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + '/' + name +
           '/' + name;
}

SiteStore::SiteStore(QString directory) : directory_(std::move(directory)) {}

QString SiteStore::filePath() const {
    return QDir(directory_).filePath(QStringLiteral("sites.json"));
}

bool SiteStore::load(SiteList &list, QString &error) const {
    list = SiteList();
    if (!QFileInfo::exists(filePath())) return true;
    QString ioError;
    const SitesRead read = readFile(filePath(), ioError);
    if (!ioError.isEmpty()) {
        error = ioError;
        return false;
    }
    if (!read.ok()) {
        error = tr("%1: %2").arg(filePath(), QString::fromStdString(read.errors.front()));
        return false;
    }
    for (const Site &s : read.sites) list.add(s);
    return true;
}

bool SiteStore::save(const SiteList &list, QString &error) const {
    if (!QDir().mkpath(directory_)) {
        error = tr("cannot make the folder %1").arg(directory_);
        return false;
    }
    return writeFile(filePath(), list.sites(), error);
}

SitesRead SiteStore::readFile(const QString &path, QString &ioError) {
    const FileKind kind = siteFileKind(path);
    if (kind == FileKind::Other) {
        ioError = tr("%1: a site file is .json or .csv").arg(path);
        return {};
    }
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        ioError = tr("cannot read %1: %2").arg(path, f.errorString());
        return {};
    }
    const QByteArray bytes = f.readAll();
    if (f.error() != QFileDevice::NoError) {
        ioError = tr("cannot read %1: %2").arg(path, f.errorString());
        return {};
    }
    return kind == FileKind::Json ? parseJson(bytes)
                                  : sitesFromCsv(std::string_view(bytes.constData(), bytes.size()));
}

bool SiteStore::writeFile(const QString &path, const std::vector<Site> &sites, QString &error) {
    const FileKind kind = siteFileKind(path);
    if (kind == FileKind::Other) {
        error = tr("%1: a site file is .json or .csv").arg(path);
        return false;
    }
    const std::string text = kind == FileKind::Json ? sitesToJson(sites) : sitesToCsv(sites);
    // Unbuffered, so that a short write (a full disk, a file size limit) is seen here: Qt 6.4's
    // buffered QSaveFile commits a file cut short as if whole.
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Unbuffered)) {
        error = tr("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    const qint64 size = static_cast<qint64>(text.size());
    if (const qint64 written = f.write(text.data(), size); written != size) {
        f.cancelWriting();
        error = tr("cannot write %1: %2 of %3 bytes written (is the disk full?)")
                        .arg(path)
                        .arg(std::max<qint64>(written, 0))
                        .arg(size);
        return false;
    }
    if (!f.commit()) {
        error = tr("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

SitesRead SiteStore::parseJson(const QByteArray &bytes) {
    SitesRead read;
    auto fail = [&](const QString &why) {
        read.errors.push_back(why.toStdString());
        return read;
    };
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(
                tr("not JSON: %1 at byte %2").arg(parseError.errorString()).arg(parseError.offset));
    const QJsonObject root = doc.object();
    if (!doc.isObject() || root.value("format").toString() != QLatin1String(kJsonFormat.data()))
        return fail(tr("not a site list (no \"format\": \"%1\")")
                            .arg(QLatin1String(kJsonFormat.data())));
    const int version = root.value("version").toInt(-1);
    if (version != kJsonVersion)
        return fail(version > kJsonVersion
                            ? tr("version %1 of the site list is newer than this program reads "
                                 "(%2)")
                                      .arg(version)
                                      .arg(kJsonVersion)
                            : tr("\"version\" must be %1").arg(kJsonVersion));
    if (!root.value("sites").isArray()) return fail(tr("\"sites\" must be an array"));
    const QJsonArray entries = root.value("sites").toArray();
    std::vector<std::string> places;
    for (qsizetype i = 0; i < entries.size(); ++i) {
        const QJsonObject o = entries[i].toObject();
        const QString name = o.value("name").toString();
        const QString where = name.isEmpty() ? tr("site %1").arg(i + 1)
                                             : tr("site %1 (\"%2\")").arg(i + 1).arg(name);
        if (!entries[i].isObject()) {
            read.errors.push_back(tr("%1: not an object").arg(where).toStdString());
            continue;
        }
        QString why;
        auto number = [&](const char *key, bool required) -> std::optional<double> {
            const QJsonValue v = o.value(QLatin1String(key));
            if (v.isDouble()) return v.toDouble();
            if ((v.isUndefined() || v.isNull()) && !required) return std::nullopt;
            if (why.isEmpty())
                why = v.isUndefined() ? tr("field \"%1\" is missing").arg(key)
                                      : tr("field \"%1\": not a number").arg(key);
            return std::nullopt;
        };
        auto text = [&](const char *key) -> std::string {
            const QJsonValue v = o.value(QLatin1String(key));
            if (v.isString()) return v.toString().toStdString();
            if (!v.isUndefined() && !v.isNull() && why.isEmpty())
                why = tr("field \"%1\": not text").arg(key);
            return {};
        };
        Site s;
        if (!o.value("name").isString()) why = tr("field \"name\" is missing or not text");
        s.name = name.toStdString();
        const auto lat = number("lat", true), lon = number("lon", true);
        s.latDeg = lat.value_or(0);
        s.lonDeg = lon.value_or(0);
        s.height = number("height", false);
        s.antennaHeight = number("antenna_height", false).value_or(0.0);
        s.accuracy = number("accuracy", false);
        s.date = text("date");
        s.method = text("method");
        s.note = text("note");
        if (!why.isEmpty()) {
            read.errors.push_back(tr("%1: %2").arg(where, why).toStdString());
            continue;
        }
        read.sites.push_back(std::move(s));
        places.push_back(where.toStdString());
    }
    if (!read.errors.empty()) {
        read.sites.clear();
        return read;
    }
    checkSitesRead(read, [&](std::size_t i) { return places[i]; });
    return read;
}

} // namespace gnss::sites
