#pragma once
// Test helper: what scanLog must count, found the plain way: one StreamDecoder and one
// EpochAssembler reading the whole log front to back (tests/tst_log_scan.cpp and the
// fuzz_log_scan harness compare scanLog's threads with it). Qt-free, for the fuzz builds.
#include "core/stream_decoder.h"
#include "state/epoch_assembler.h"
#include "state/log_scan.h"

#include <cstddef>
#include <string_view>

namespace gnss::test {

// `chunk`: the bytes fed at a time (0: the whole log at once).
inline LogScanResult scanFrontToBack(std::string_view log, const DialectRegistry &registry,
                                     const DecoderOptions &options, std::size_t chunk = 0) {
    StreamDecoder dec(registry, options);
    EpochAssembler assembler;
    LogScanResult r;
    auto onEpoch = [&](const Epoch &) { ++r.epochs; };
    auto onSentence = [&](const SentenceEvent &ev) {
        if (!ev.message) return;
        assembler.setDialect(dec.dialect());
        assembler.add(ev.sentence, *ev.message, onEpoch);
    };
    if (chunk == 0)
        dec.feed(log, onSentence);
    else
        for (std::size_t pos = 0; pos < log.size(); pos += chunk)
            dec.feed(log.substr(pos, chunk), onSentence);
    dec.finish();
    assembler.flush(onEpoch);
    r.framer = dec.framerStats();
    r.addresses = dec.addressStats();
    r.dialect = dec.dialect();
    return r;
}

} // namespace gnss::test
