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
// schema does not know. Values are checked where they are about to be sent (refusedValues, the
// engine's apply): a receiver may report, and a profile carry, a value its schema would not take
// (the VT002's unset user datum reads as 290 and 6370000 m), which is harmless while it is not
// sent.
#include "core/dialect.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <string>
#include <string_view>
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

// Why `p` must not go to a receiver of `dialect` whose model is `receiverModel`: it is for
// another dialect, or names another model (both known); empty when it may.
QString profileMismatch(const Profile &p, const Dialect *dialect, std::string_view receiverModel);

// The refusal of each of `values` that its command would not take (out of range, not one of the
// options, not a number), one text each; empty when every one may be sent.
QStringList refusedValues(const Dialect &dialect, const std::vector<KeyValue> &values);

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
