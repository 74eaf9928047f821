// Fuzz harness: a settings profile read from bytes (config::profileFromJson, the in-memory half
// of loadProfile), with no dialect or with each built-in dialect's schema.
//
// Input: byte 0 picks the dialect (0: none; 1-4: nvs, geostar, nemerix, nmea; wraps), the rest
// is the file. Checks that a refusal says why; that an accepted profile keeps every string
// value of the file's "values" (none dropped silently), under the schema's own keys when a
// dialect is given; and that writing it out and reading it back gives the same profile.
#include "builtin/dialects.h"
#include "config/setting_values.h"
#include "config/settings_profile.h"
#include "fuzz_common.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <map>

using namespace gnss;
using namespace gnss::fuzz;

namespace {

const Dialect *pickDialect(std::uint8_t b) {
    static const DialectRegistry reg = makeBuiltinRegistry();
    const auto dialects = reg.dialects();
    const std::size_t k = b % (dialects.size() + 1);
    return k == 0 ? nullptr : dialects[k - 1];
}

GNSS_FUZZ_NO_COVERAGE std::string describe(const config::Profile &p) {
    std::string s = std::to_string(p.version) + " " + p.dialect + " " + p.model + " " + p.firmware +
                    " " + p.created + " {";
    for (const auto &kv : p.values) s += kv.key + "=" + kv.value + ";";
    s += "} [";
    for (const auto &k : p.writeOnly) s += k + ";";
    return s + "]";
}

// The same profile. Without a dialect, keys are kept as the file has them: a key that is not
// valid UTF-16 (a lone surrogate) is read as U+FFFD, which may change the order of the JSON
// object's keys and make two keys one when written back; compare those values as a map.
GNSS_FUZZ_NO_COVERAGE bool same(const config::Profile &a, const config::Profile &b, bool ordered) {
    if (a.version != b.version || a.dialect != b.dialect || a.model != b.model ||
        a.firmware != b.firmware || a.created != b.created || a.writeOnly != b.writeOnly)
        return false;
    if (ordered) {
        if (a.values.size() != b.values.size()) return false;
        for (std::size_t i = 0; i < a.values.size(); ++i)
            if (a.values[i].key != b.values[i].key || a.values[i].value != b.values[i].value)
                return false;
        return true;
    }
    auto map = [](const config::Profile &p) {
        std::map<std::string, std::string> m;
        for (const auto &kv : p.values) m[kv.key] = kv.value;
        return m;
    };
    return map(a) == map(b);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    Input in(data, size);
    const Dialect *dialect = pickDialect(in.byte());
    const std::string_view text = in.rest();
    const QByteArray json(text.data(), static_cast<qsizetype>(text.size()));

    config::Profile p;
    QString error;
    if (!config::profileFromJson(json, p, &error, dialect)) {
        check(!error.isEmpty(), "a profile was refused without a reason");
        return 0;
    }

    // Every string value of the file is in the profile (values that are not strings refuse it).
    const QJsonObject values = QJsonDocument::fromJson(json).object()["values"].toObject();
    checkEqual<std::size_t>(p.values.size(), static_cast<std::size_t>(values.size()),
                            "an accepted profile lost values");
    if (dialect) {
        for (const auto &kv : p.values) {
            const SettingDef *def = findSetting(dialect->settings, kv.key);
            check(def && def->key == kv.key && config::isWritable(*def),
                  "an accepted profile holds a key that is not one of the schema's", kv.key);
        }
    }

    // Written out and read back: the same profile.
    config::Profile again;
    if (!config::profileFromJson(config::profileToJson(p), again, &error, dialect))
        fail("a profile this program wrote is refused", error.toStdString() + "\n  " + describe(p));
    if (!same(p, again, dialect != nullptr))
        fail("a profile changed when written and read back",
             describe(p) + "\n  vs\n  " + describe(again));
    return 0;
}
