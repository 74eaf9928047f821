#include "core/stream_decoder.h"

#include <cstring>

namespace gnss {
namespace {

constexpr std::size_t kMaxTrackedAddresses = 4096;

inline std::uint64_t load32(const char *p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

// Packs an address of up to 8 characters into a cache key (0 = not cacheable): its bytes in
// order, zeros above. Read with fixed-size loads inside the address (two that may overlap, OR-ed
// where they do: the same byte at the same place), not a memcpy of its length, which is a call,
// and then a byte-wise store read back whole (a store-forwarding stall on every sentence).
inline std::uint64_t packAddress(std::string_view a) {
    const std::size_t n = a.size();
    const char *p = a.data();
    if (n - 1 >= 8) return 0; // empty or longer than 8
    if (n >= 4) return load32(p) | load32(p + n - 4) << (8 * (n - 4));
    const auto byte = [p](std::size_t i) -> std::uint64_t {
        return static_cast<unsigned char>(p[i]);
    };
    return byte(0) | byte(n / 2) << (8 * (n / 2)) | byte(n - 1) << (8 * (n - 1));
}

inline std::size_t hashKey(std::uint64_t k) {
    k ^= k >> 29;
    k *= 0xbf58476d1ce4e5b9ULL;
    k ^= k >> 32;
    return static_cast<std::size_t>(k);
}

const char *hexByte(std::uint8_t v, char *buf) {
    static const char hex[] = "0123456789ABCDEF";
    buf[0] = hex[v >> 4];
    buf[1] = hex[v & 15];
    buf[2] = '\0';
    return buf;
}

} // namespace

void writeSentenceEventJson(JsonWriter &w, const SentenceEvent &ev) {
    const Sentence &s = ev.sentence;
    w.beginObject().field("line", s.line()).field("address", s.address());
    w.field("talker", s.talker()).field("type", s.type());
    w.field("checksum", toString(s.checksum()));
    if (ev.message) {
        w.key("data");
        ev.message->writeJson(w);
    } else {
        w.field("error", ev.error);
    }
    w.endObject();
}

StreamDecoder::StreamDecoder(const DialectRegistry &registry, DecoderOptions options)
    : registry_(registry), options_(std::move(options)) {
    if (options_.dialect != "auto" && !options_.dialect.empty()) {
        dialect_ = registry_.find(options_.dialect);
        autoDetect_ = false;
    }
}

void StreamDecoder::setDialect(const Dialect *d) {
    dialect_ = d;
    autoDetect_ = d == nullptr;
    forgetAddresses();
}

std::uint32_t StreamDecoder::statsIndexFor(std::string_view address) {
    auto it = statsByAddress_.find(std::string(address));
    if (it != statsByAddress_.end()) return it->second;
    if (stats_.size() >= kMaxTrackedAddresses) {
        // A stream of garbage addresses must not grow memory without bound.
        auto other = statsByAddress_.find("(other)");
        if (other != statsByAddress_.end()) return other->second;
        address = "(other)";
    }
    const auto idx = static_cast<std::uint32_t>(stats_.size());
    stats_.push_back(AddressStats{std::string(address)});
    statsByAddress_.emplace(std::string(address), idx);
    return idx;
}

StreamDecoder::Resolved StreamDecoder::resolveSlow(std::string_view address) {
    std::string_view lookupAddress = address;
    for (const auto &[alias, canonical] : options_.addressAliases) {
        if (address.size() >= alias.size() && address.substr(0, alias.size()) == alias) {
            aliasBuffer_ = canonical;
            aliasBuffer_.append(address.substr(alias.size()));
            lookupAddress = aliasBuffer_;
            break;
        }
    }
    return {registry_.lookup(lookupAddress, dialect_), statsIndexFor(address)};
}

void StreamDecoder::forgetAddresses() {
    cache_ = {};
    cacheUsed_ = 0;
    last_ = {};
}

StreamDecoder::Resolved StreamDecoder::resolve(std::string_view address) {
    const std::uint64_t key = packAddress(address);
    if (key == 0) return resolveSlow(address);
    // The address of the sentence before, most often (a receiver sends a system's GSVs and a
    // combined fix's GSAs one after the other): one comparison. The decode waits on this
    // answer (its function is called through it), so the hash and the table's load were on
    // every sentence's path.
    if (key == last_.key) return {last_.match, last_.statsIndex};
    std::size_t slot = hashKey(key) & (cache_.size() - 1);
    for (std::size_t probe = 0; probe < cache_.size(); ++probe) {
        CacheEntry &e = cache_[slot];
        if (e.key == key) { // nearly always, at the first probe
            last_ = e;
            return {e.match, e.statsIndex};
        }
        if (e.key == 0) { // a free slot (no address packs to 0): not met before
            Resolved r = resolveSlow(address);
            if (cacheUsed_ < cache_.size() * 3 / 4) {
                e.key = key;
                e.match = r.match;
                e.statsIndex = r.statsIndex;
                ++cacheUsed_;
            }
            return r;
        }
        slot = (slot + 1) & (cache_.size() - 1);
    }
    return resolveSlow(address);
}

bool StreamDecoder::checksumAcceptable(const Sentence &s, const Dialect *ruleDialect) const {
    switch (s.checksum()) {
    case ChecksumStatus::Ok: return true;
    case ChecksumStatus::Bad: return options_.lenient;
    case ChecksumStatus::Missing:
        return options_.lenient || (ruleDialect && ruleDialect->checksumOptional) ||
               (dialect_ && dialect_->checksumOptional);
    }
    return false;
}

void StreamDecoder::finish() {
    framer_.finish();
    if (options_.frameRtcm) rtcm_.finish([this](const rtcm::RtcmFrame &f) { onFrame(f); });
}

void StreamDecoder::onFrame(const rtcm::RtcmFrame &f) {
    ++rtcmTypes_[f.messageNumber()];
    if (frameHandler_) frameHandler_(f);
}

void StreamDecoder::feed(std::string_view bytes, const Handler &handler) {
    framer_.feed(bytes, [&](std::string_view line) { decodeLine(line, handler); });
    if (options_.frameRtcm) rtcm_.feed(bytes, [this](const rtcm::RtcmFrame &f) { onFrame(f); });
}

void StreamDecoder::decodeLine(std::string_view line, const Handler &handler) {
    Sentence s;
    if (!s.parse(line)) {
        ++malformed_;
        AddressStats &st = stats_[statsIndexFor("(malformed)")];
        ++st.sentences;
        ++st.decodeErrors;
        handler(SentenceEvent{s, nullptr, s.error(), nullptr});
        return;
    }
    const Resolved r = resolve(s.address());
    AddressStats &st = stats_[r.statsIndex];
    ++st.sentences;
    if (s.checksum() == ChecksumStatus::Bad) ++st.checksumBad;
    if (s.checksum() == ChecksumStatus::Missing) ++st.checksumMissing;

    if (!r.match.rule) {
        ++st.unknown;
        handler(SentenceEvent{s, nullptr, QT_TRANSLATE_NOOP("Refusal", "unknown sentence"), nullptr,
                              true});
        return;
    }
    if (s.checksum() != ChecksumStatus::Ok && !checksumAcceptable(s, r.match.dialect)) {
        ++st.rejected;
        char a[3], b[3];
        if (s.checksum() == ChecksumStatus::Bad) {
            problem_ =
                    refusal(QT_TRANSLATE_NOOP("Refusal", "checksum mismatch: sent %1, computed %2"),
                            {s.checksumPlaceholder() ? "?" : hexByte(s.declaredChecksum(), a),
                             hexByte(s.computedChecksum(), b)});
            handler(SentenceEvent{s, nullptr, problem_.text, r.match.dialect, false, &problem_});
        } else {
            handler(SentenceEvent{s, nullptr, QT_TRANSLATE_NOOP("Refusal", "checksum missing"),
                                  r.match.dialect});
        }
        return;
    }

    const Dialect *decodeDialect = dialect_ ? dialect_ : r.match.dialect;
    bool emitted = false;
    auto onMessage = [&](const Message &m) {
        emitted = true;
        ++st.decoded;
        handler(SentenceEvent{s, &m, {}, r.match.dialect});
    };
    DecodeContext ctx(decodeDialect, onMessage); // FunctionRef: the lambda must outlive ctx
    const bool ok = r.match.rule->decode(s, ctx);
    if (!ok) {
        ++st.decodeErrors;
        const bool formed = ctx.problem.form && ctx.problem.text == ctx.error;
        handler(SentenceEvent{s, nullptr,
                              ctx.error.empty() ? QT_TRANSLATE_NOOP("Refusal", "malformed")
                                                : std::string_view(ctx.error),
                              r.match.dialect, false, formed ? &ctx.problem : nullptr});
        return;
    }
    (void)emitted;
    // Auto detection: the first vendor sentence that decodes names the dialect.
    if (autoDetect_ && !dialect_ && r.match.dialect && r.match.rule->match == AddressMatch::Whole &&
        s.checksum() != ChecksumStatus::Bad) {
        dialect_ = r.match.dialect;
        forgetAddresses();
    }
}

} // namespace gnss
