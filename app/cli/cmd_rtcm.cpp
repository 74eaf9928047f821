// gnss-cli rtcm: an RTCM 3 stream (file or standard input) as JSON, one object per message on
// standard output, the counts at the end on standard error.
#include "cli/cli_commands.h"
#include "cli/input_reader.h"
#include "rtcm/rtcm_json.h"
#include "rtcm/rtcm_stream_decoder.h"

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace gnss::cli {

int cmdRtcm(const CliContext &ctx) {
    const std::vector<std::string> &files = ctx.args.positionals();
    if (files.size() > 1) {
        std::fprintf(stderr, "gnss-cli: one input file at most (or - for standard input)\n");
        return 2;
    }
    const std::string input = files.empty() ? "-" : files.front();

    rtcm::RtcmStreamDecoder dec;
    std::string out; // written in 64 KiB pieces, not per line
    auto onMessage = [&out](const rtcm::RtcmMessage &m) {
        JsonWriter w(out);
        rtcm::writeRtcmJson(w, m);
        out.push_back('\n');
        if (out.size() > (1 << 16)) {
            std::fwrite(out.data(), 1, out.size(), stdout);
            out.clear();
        }
    };
    std::string error;
    const bool ok = readInput(
            input, [&](std::string_view chunk) { dec.feed(chunk, onMessage); }, error);
    dec.finish(onMessage);
    std::fwrite(out.data(), 1, out.size(), stdout);
    std::fflush(stdout);
    if (!ok) std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());

    std::string summary;
    JsonWriter w(summary);
    rtcm::writeRtcmSummaryJson(w, dec);
    std::fprintf(stderr, "%s\n", summary.c_str());
    return ok ? 0 : 1;
}

} // namespace gnss::cli
