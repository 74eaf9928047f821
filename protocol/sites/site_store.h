#pragma once
// The user's site list on disk (Qt Core): sites.json in the user's data folder, shared by the GUI
// and gnss-cli, written atomically; and the site files a user exports and imports (.json, .csv),
// JSON read with Qt's parser. The list itself and the formats are plain C++ (site.h,
// site_formats.h).
#include "sites/site_formats.h"

#include <QCoreApplication>
#include <QString>

namespace gnss::sites {

class SiteStore {
    Q_DECLARE_TR_FUNCTIONS(SiteStore)
public:
    // The environment variable that, when set, names the folder instead (for tests).
    static constexpr const char *kDirectoryVariable = "GNSS_WORKBENCH_DATA_DIR";
    // $GNSS_WORKBENCH_DATA_DIR, else the GUI's AppDataLocation, named the same whichever program
    // asks (~/.local/share/GNSS Workbench/GNSS Workbench on Linux).
    static QString defaultDirectory();

    explicit SiteStore(QString directory = defaultDirectory());
    QString directory() const { return directory_; }
    QString filePath() const; // directory/sites.json

    // The list from sites.json; none there is an empty list. False, with why, when it cannot be
    // read or is malformed (the list is left empty).
    bool load(SiteList &list, QString &error) const;
    // Writes sites.json through a temporary file renamed over it (QSaveFile), making the folder
    // when there is none: on failure the old file is as it was.
    bool save(const SiteList &list, QString &error) const;

    // A site file, its format by its extension (.json or .csv, any case). `ioError` is set when
    // it cannot be read (or has another extension), else the result holds the sites or what is
    // wrong with them.
    static SitesRead readFile(const QString &path, QString &ioError);
    static bool writeFile(const QString &path, const std::vector<Site> &sites, QString &error);
    // The JSON document (site_formats.h), checked as sitesFromCsv checks its rows.
    static SitesRead parseJson(const QByteArray &bytes);

private:
    QString directory_;
};

} // namespace gnss::sites
