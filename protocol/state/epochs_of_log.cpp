#include "state/epochs_of_log.h"

#include "core/stream_decoder.h"
#include "state/epoch.h"
#include "state/epoch_assembler.h"

namespace gnss {

bool epochsOfLog(std::string_view log, const DialectRegistry &registry, const Dialect *dialect,
                 FunctionRef<void(const Epoch &)> onEpoch, const std::atomic<bool> *cancel) {
    StreamDecoder decoder(registry, DecoderOptions{});
    if (dialect) decoder.setDialect(dialect);
    EpochAssembler assembler(decoder.dialect());
    auto keep = [&](const Epoch &e) { onEpoch(e); };
    constexpr std::size_t kChunk = 1 << 20;
    for (std::size_t at = 0; at < log.size(); at += kChunk) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return false;
        decoder.feed(log.substr(at, kChunk), [&](const SentenceEvent &ev) {
            if (!ev.message) return;
            assembler.setDialect(decoder.dialect());
            assembler.add(ev.sentence, *ev.message, keep);
        });
    }
    decoder.finish();
    assembler.flush(keep);
    return true;
}

} // namespace gnss
