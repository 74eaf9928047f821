#pragma once
// Test helper: what a stretch of simulator output contains, decoded with the real stream decoder.
#include "builtin_registry.h"
#include "core/stream_decoder.h"

#include <map>
#include <string>
#include <vector>

namespace gnss::test {

struct DecodedLine {
    std::string line;    // the sentence without terminator
    std::string address; // "GPGGA", "PNVGBSS"
    bool checksumOk = false;
    bool decoded = false;
    std::string error;
};

struct OutputSummary {
    std::vector<DecodedLine> lines;
    std::map<std::string, int> byAddress;
    std::map<std::string, int> byType; // GGA, GSV (talker dropped; proprietary whole)
    int checksumErrors = 0;
    int decodeErrors = 0;
    std::vector<std::string> all(std::string_view typeOrAddress) const {
        std::vector<std::string> out;
        for (const auto &l : lines)
            if (l.address == typeOrAddress ||
                (l.address.size() == 5 && l.address[0] == 'G' &&
                 std::string_view(l.address).substr(2) == typeOrAddress))
                out.push_back(l.line);
        return out;
    }
    // How many sentences of a type (GGA, PNVGBSS) there were.
    int count(const std::string &type) const {
        auto it = byType.find(type);
        return it == byType.end() ? 0 : it->second;
    }
};

inline OutputSummary summarize(const std::string &bytes, std::string_view dialect = "auto") {
    DecoderOptions o;
    o.dialect = std::string(dialect);
    StreamDecoder d(builtinRegistry(), o);
    OutputSummary s;
    d.feed(bytes, [&](const SentenceEvent &ev) {
        DecodedLine l;
        l.line = std::string(ev.sentence.line());
        l.address = std::string(ev.sentence.address());
        l.checksumOk = ev.sentence.checksum() == ChecksumStatus::Ok;
        l.decoded = ev.message != nullptr;
        l.error = std::string(ev.error);
        ++s.byAddress[l.address];
        const bool standard = l.address.size() == 5 && l.address[0] == 'G';
        ++s.byType[standard ? l.address.substr(2) : l.address];
        if (!l.checksumOk) ++s.checksumErrors;
        if (!l.decoded) ++s.decodeErrors;
        s.lines.push_back(std::move(l));
    });
    return s;
}

} // namespace gnss::test
