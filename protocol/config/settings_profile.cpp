#include "config/settings_profile.h"

#include "config/utf8_text.h"

#include "config/refusal_text.h"
#include "config/setting_values.h"

#include "core/settings_plan.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace gnss::config {

namespace {
constexpr auto kFormat = "gnss-workbench-settings";

} // namespace

QByteArray profileToJson(const Profile &p) {
    QJsonObject o;
    o["format"] = kFormat;
    o["version"] = p.version;
    o["dialect"] = qs(p.dialect);
    o["model"] = qs(p.model);
    o["firmware"] = qs(p.firmware);
    o["created"] = qs(p.created);
    QJsonObject values;
    for (const auto &kv : p.values) values[qs(kv.key)] = qs(kv.value);
    o["values"] = values;
    QJsonArray wo;
    for (const auto &k : p.writeOnly) wo.append(qs(k));
    o["write_only"] = wo;
    return QJsonDocument(o).toJson(QJsonDocument::Indented);
}

bool profileFromJson(const QByteArray &json, Profile &out, QString *error, const Dialect *dialect) {
    auto fail = [&](const QString &why) {
        if (error) *error = why;
        return false;
    };
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (doc.isNull() || !doc.isObject())
        return fail(QObject::tr("not a settings profile: %1").arg(pe.errorString()));
    const QJsonObject o = doc.object();
    if (o["format"].toString() != kFormat)
        return fail(QObject::tr("not a settings profile (format is '%1', expected '%2')")
                            .arg(o["format"].toString(), kFormat));
    const int version = o["version"].toInt(-1);
    if (version < 1 || version > Profile::kVersion)
        return fail(QObject::tr("profile version %1 is not supported (this program reads "
                                "version 1 to %2)")
                            .arg(version)
                            .arg(Profile::kVersion));
    Profile p;
    p.version = version;
    p.dialect = o["dialect"].toString().toStdString();
    p.model = o["model"].toString().toStdString();
    p.firmware = o["firmware"].toString().toStdString();
    p.created = o["created"].toString().toStdString();
    if (const QString why = profileMismatch(p, dialect, {}); !why.isEmpty()) return fail(why);
    const QJsonObject values = o["values"].toObject();
    QStringList unknown, invalid;
    for (auto it = values.begin(); it != values.end(); ++it) {
        if (!it.value().isString()) {
            invalid << QObject::tr("%1: the value must be a string").arg(it.key());
            continue;
        }
        p.values.push_back({it.key().toStdString(), it.value().toString().toStdString()});
    }
    for (const auto &v : o["write_only"].toArray())
        p.writeOnly.push_back(v.toString().toStdString());
    if (dialect) {
        // Values are checked when applied (the dialect's encoder validates everything before
        // anything is sent). Schema order, so that files and diffs read in the order of the forms,
        // under the schema's own keys: a key may be the spec's name alone ("PVTRATE"), as users
        // type it, and must not be lost for that.
        std::vector<KeyValue> ordered;
        for (const auto &def : dialect->settings) {
            const KeyValue *given = nullptr;
            for (const auto &kv : p.values) {
                if (findSetting(dialect->settings, kv.key) != &def) continue;
                if (given)
                    invalid << QObject::tr("%1: given twice (as %2 and %3)")
                                       .arg(qs(def.key), qs(given->key), qs(kv.key));
                given = &kv;
            }
            if (given) ordered.push_back({std::string(def.key), given->value});
        }
        for (const auto &kv : p.values) {
            const SettingDef *def = findSetting(dialect->settings, kv.key);
            if (!def || !isWritable(*def)) {
                unknown << qs(kv.key);
                continue;
            }
        }
        p.values = std::move(ordered);
    }
    if (!unknown.isEmpty())
        return fail(QObject::tr("the profile names settings the %1 dialect cannot set: %2")
                            .arg(qs(dialect->id), unknown.join(", ")));
    if (!invalid.isEmpty()) return fail(invalid.join("; "));
    out = std::move(p);
    return true;
}

QString profileMismatch(const Profile &p, const Dialect *dialect, std::string_view receiverModel) {
    if (dialect && p.dialect != dialect->id)
        return QObject::tr("the profile is for dialect '%1', the receiver speaks '%2'")
                .arg(qs(p.dialect), qs(dialect->id));
    std::string_view profileModel = p.model;
    if (dialect)
        for (const auto &[former, now] : dialect->formerModelNames)
            if (profileModel == former) profileModel = now;
    if (!profileModel.empty() && !receiverModel.empty() && profileModel != receiverModel)
        return QObject::tr("the profile is for the %1, the receiver is a %2: export a profile "
                           "from a %2, or edit the file's \"model\" if the settings suit it")
                .arg(qs(p.model), qs(receiverModel));
    return {};
}

QStringList refusedValues(const Dialect &dialect, const std::vector<KeyValue> &values) {
    QStringList out;
    for (const KeyValue &kv : values) {
        std::vector<PlannedCommand> plan;
        if (const Refusal why = planWrites(dialect, {&kv, 1}, plan); !why.empty())
            out << refusalText(why, dialect.id);
    }
    return out;
}

bool saveProfile(const QString &path, const Profile &p, QString *error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(profileToJson(p)) < 0 || !f.commit()) {
        if (error) *error = QObject::tr("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

bool loadProfile(const QString &path, Profile &out, QString *error, const Dialect *dialect) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error) *error = QObject::tr("cannot read %1: %2").arg(path, f.errorString());
        return false;
    }
    return profileFromJson(f.readAll(), out, error, dialect);
}

} // namespace gnss::config
