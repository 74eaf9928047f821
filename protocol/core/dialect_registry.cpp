#include "core/dialect_registry.h"

namespace gnss {

SatelliteRef DecodeContext::mapSatelliteByDialect(Constellation system, int id) const {
    return dialect_->mapSatellite(system, id);
}

std::string_view toString(ReceiverAction a) {
    switch (a) {
    case ReceiverAction::SaveToFlash: return "save";
    case ReceiverAction::RestoreDefaults: return "defaults";
    case ReceiverAction::ColdStart: return "cold";
    case ReceiverAction::WarmStart: return "warm";
    case ReceiverAction::HotStart: return "hot";
    }
    return {};
}

const ActionDef *findAction(const Dialect &d, ReceiverAction action) {
    for (const auto &a : d.actions)
        if (a.action == action) return &a;
    return nullptr;
}

DialectRegistry::DialectRegistry(std::span<const SentenceRule> standardRules,
                                 std::vector<const Dialect *> dialects)
    : dialects_(std::move(dialects)) {
    for (const auto &r : standardRules) {
        if (r.match == AddressMatch::Type) types_.emplace(r.address, Match{&r, nullptr});
        if (r.match == AddressMatch::Query) query_ = Match{&r, nullptr};
    }
    for (const Dialect *d : dialects_) {
        for (const auto &r : d->rules) {
            if (r.match == AddressMatch::Whole) whole_.emplace(r.address, Match{&r, d});
            if (r.match == AddressMatch::Type) types_.emplace(r.address, Match{&r, d});
        }
    }
}

const Dialect *DialectRegistry::find(std::string_view id) const {
    for (const Dialect *d : dialects_)
        if (d->id == id) return d;
    return nullptr;
}

DialectRegistry::Match DialectRegistry::lookup(std::string_view address,
                                               const Dialect *preferred) const {
    if (preferred) {
        for (const auto &r : preferred->rules)
            if (r.match == AddressMatch::Whole && r.address == address) return {&r, preferred};
    }
    if (auto it = whole_.find(address); it != whole_.end()) return it->second;
    if (address.size() >= 3 && address.front() != 'P') {
        const std::string_view type = address.substr(2);
        if (preferred) {
            for (const auto &r : preferred->rules)
                if (r.match == AddressMatch::Type && r.address == type) return {&r, preferred};
        }
        if (auto it = types_.find(type); it != types_.end()) return it->second;
    }
    if (address.size() == 5 && address[4] == 'Q' && address.front() != 'P') return query_;
    return {};
}

} // namespace gnss
