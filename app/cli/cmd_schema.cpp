// gnss-cli schema DIALECT | encode DIALECT KEY=VALUE... | encode DIALECT --query KEY...
// Generic over every dialect's settings schema and encoders: no vendor is named here.
#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "core/json_writer.h"
#include "core/sentence_builder.h"
#include "core/settings_plan.h"

#include <cstdio>
#include <string>

namespace gnss::cli {
namespace {

const Dialect *dialectArg(const CliContext &ctx, const std::vector<std::string> &pos) {
    if (pos.empty()) {
        std::string known;
        for (const Dialect *k : ctx.registry.dialects())
            known += (known.empty() ? "" : ", ") + std::string(k->id);
        std::fprintf(stderr, "gnss-cli: name a dialect (%s)\n", known.c_str());
        return nullptr;
    }
    const Dialect *d = ctx.registry.find(pos.front());
    if (!d) {
        std::string known;
        for (const Dialect *k : ctx.registry.dialects()) known += " " + std::string(k->id);
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s' (known:%s)\n", pos.front().c_str(),
                     known.c_str());
    }
    return d;
}

void writeSetting(JsonWriter &w, const SettingDef &s) {
    w.beginObject().field("key", s.key).field("label", s.label).field("group", s.group);
    w.field("type", toString(s.type)).field("default", s.defaultValue).field("unit", s.unit);
    if (s.min) w.field("min", *s.min);
    if (s.max) w.field("max", *s.max);
    if (!s.options.empty()) {
        w.key("options").beginArray();
        for (const auto &o : s.options)
            w.beginObject().field("value", o.value).field("label", o.label).endObject();
        w.endArray();
    }
    w.field("access", toString(s.access)).field("read_back", s.readBack).field("write", s.write);
    w.field("help", s.help).endObject();
}

} // namespace

int cmdSchema(const CliContext &ctx) {
    const Dialect *d = dialectArg(ctx, ctx.args.positionals());
    if (!d) return 2;
    std::string out;
    JsonWriter w(out);
    w.beginArray();
    for (const auto &s : d->settings) writeSetting(w, s);
    w.endArray();
    out += '\n';
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
}

int cmdEncode(const CliContext &ctx) {
    const Args &args = ctx.args;
    const Dialect *d = dialectArg(ctx, args.positionals());
    if (!d) return 2;
    if (const auto prefix = args.option("prefix")) {
        if (d->renamablePrefix.empty()) {
            std::fprintf(stderr, "gnss-cli: the %s dialect has no renamable prefix\n",
                         std::string(d->id).c_str());
            return 2;
        }
        if (const std::string err = checkAddressPrefix(*prefix); !err.empty()) {
            std::fprintf(stderr, "gnss-cli: %s\n", err.c_str());
            return 2;
        }
    }
    std::vector<std::string> rest(args.positionals().begin() + 1, args.positionals().end());
    if (rest.empty()) {
        std::fprintf(stderr, "gnss-cli: encode %s needs KEY=VALUE... or --query KEY...\n",
                     std::string(d->id).c_str());
        return 2;
    }
    EncodeResult result;
    if (d->settings.empty()) {
        std::fprintf(stderr, "gnss-cli: the %s dialect has no settings\n",
                     std::string(d->id).c_str());
        return 2;
    }
    // Every key in the forms people write it ("PVTRATE", "rtk.pvtrate"); an unknown or ambiguous
    // one is a wrong request (exit 2), said with the keys it could mean.
    for (const auto &k : rest) {
        const std::string key = args.flag("query") ? k : k.substr(0, k.find('='));
        if (!key.empty() && key != "all" && !findSetting(d->settings, key)) {
            std::fprintf(stderr, "gnss-cli: %s\n", unknownSetting(*d, key).text.c_str());
            return 2;
        }
    }
    if (args.flag("query")) {
        result = encodeQueries(*d, rest);
    } else {
        std::vector<KeyValue> values;
        for (const auto &kv : rest) {
            const auto eq = kv.find('=');
            if (eq == std::string::npos || eq == 0) {
                std::fprintf(stderr, "gnss-cli: expected KEY=VALUE, got '%s'\n", kv.c_str());
                return 2;
            }
            values.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
        }
        result = encodeSettings(*d, values);
        refuseLongSentences(result, d->maxSentenceLength);
    }
    if (!result.ok()) {
        // A value its command cannot carry: the request is wrong, nothing is printed.
        std::fprintf(stderr, "gnss-cli: %s\n", result.error.c_str());
        return 2;
    }
    const auto prefix = args.option("prefix");
    for (const auto &s : result.sentences) {
        const std::string out = prefix ? renameAddressPrefix(s, d->renamablePrefix, *prefix) : s;
        std::printf("%s\n", out.c_str());
    }
    return 0;
}

} // namespace gnss::cli
