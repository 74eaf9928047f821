#include "rtcm/rtcm_stream_decoder.h"

namespace gnss::rtcm {

void RtcmStreamDecoder::onFrame(const RtcmFrame &f, const Handler &handler) {
    const RtcmMessage m = decodeMessage(f.payload());
    ++perType_[m.number & 0xFFF];
    if (!m.error.empty()) ++decodeErrors_;
    handler(m);
}

void RtcmStreamDecoder::feed(std::string_view bytes, const Handler &handler) {
    framer_.feed(bytes, [&](const RtcmFrame &f) { onFrame(f, handler); });
}

void RtcmStreamDecoder::finish(const Handler &handler) {
    framer_.finish([&](const RtcmFrame &f) { onFrame(f, handler); });
}

std::vector<std::pair<unsigned, std::uint64_t>> RtcmStreamDecoder::typeCounts() const {
    std::vector<std::pair<unsigned, std::uint64_t>> out;
    for (unsigned n = 0; n < perType_.size(); ++n)
        if (perType_[n]) out.emplace_back(n, perType_[n]);
    return out;
}

} // namespace gnss::rtcm
