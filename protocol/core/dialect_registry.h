#pragma once
// DialectRegistry: the dialects the program knows, and sentence lookup across them.
// Built once by the application (see protocol/dialects.h) and injected where needed.
#include "core/dialect.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace gnss {

class DialectRegistry {
public:
    // `standardRules`: the standard sentence table (nmea/nmea_rules.h), used by every dialect.
    DialectRegistry(std::span<const SentenceRule> standardRules,
                    std::vector<const Dialect *> dialects);

    std::span<const Dialect *const> dialects() const { return dialects_; }
    const Dialect *find(std::string_view id) const;

    struct Match {
        const SentenceRule *rule = nullptr;
        const Dialect *dialect = nullptr; // the dialect that owns the rule (nullptr: standard)
    };
    // Whole address first (the preferred dialect's, then any), then talker + type (the preferred
    // dialect's, then standard, then any), then the query form.
    Match lookup(std::string_view address, const Dialect *preferred) const;

private:
    std::vector<const Dialect *> dialects_;
    std::unordered_map<std::string_view, Match> whole_;
    std::unordered_map<std::string_view, Match> types_;
    Match query_;
};

} // namespace gnss
