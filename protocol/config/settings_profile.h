#pragma once
// A settings profile: one receiver's settings carried to others, as a versioned JSON file.
//
//   {"format": "gnss-workbench-settings", "version": 1, "dialect": "nvs",
//    "model": "NV08C-RTK", "firmware": "...", "created": "2024-03-15T10:00:00Z",
//    "values": {"rtk.MODE": "2", ...},
//    "write_only": ["port.COM1.baud", ...]}     // values the receiver cannot report: set by
//                                                // this program, not read back
//
// Reading a file checks the format, refuses a newer version and names any key the dialect's
// schema does not know.
#include "core/dialect.h"

#include <QByteArray>
#include <QString>

#include <string>
#include <vector>

namespace gnss::config {

struct Profile {
    static constexpr int kVersion = 1;
    int version = kVersion;
    std::string dialect, model, firmware, created;
    std::vector<KeyValue> values; // schema order
    std::vector<std::string> writeOnly;
};

QByteArray profileToJson(const Profile &p);
// False with `error` set when the text is not a profile this version can read. With `dialect`
// given, every key must be one of its settings (actions excluded) and every value valid.
bool profileFromJson(const QByteArray &json, Profile &out, QString *error,
                     const Dialect *dialect = nullptr);

bool saveProfile(const QString &path, const Profile &p, QString *error);
bool loadProfile(const QString &path, Profile &out, QString *error,
                 const Dialect *dialect = nullptr);

// One line of a difference between a profile and the receiver.
struct DiffEntry {
    std::string key;
    std::string profileValue;
    std::string receiverValue; // empty when unknown
    bool receiverKnown = false;
};

} // namespace gnss::config
