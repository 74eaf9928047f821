// gnss-cli decode | epochs | stats: read a log (or standard input) through the decoder.
#include "cli/cli_args.h"
#include "cli/cli_commands.h"
#include "cli/input_reader.h"
#include "core/sentence_builder.h"
#include "core/stream_decoder.h"
#include "state/epoch_assembler.h"
#include "state/log_scan.h"

#include <algorithm>
#include <cstdlib>
#include <thread>

#include <chrono>
#include <cstdio>
#include <string>

namespace gnss::cli {
namespace {

// Buffered standard output: one fwrite per 64 KiB, not per line.
class Output {
public:
    ~Output() { flush(); }
    std::string &buffer() { return buf_; }
    void lineDone() {
        buf_.push_back('\n');
        if (buf_.size() > (1 << 16)) flush();
    }
    void flush() {
        if (!buf_.empty()) std::fwrite(buf_.data(), 1, buf_.size(), stdout);
        buf_.clear();
    }

private:
    std::string buf_;
};

struct CommonOptions {
    DecoderOptions decoder;
    std::string input;
    bool json = false;
};

bool parseCommon(const CliContext &ctx, CommonOptions &out) {
    const Args &args = ctx.args;
    out.decoder.dialect = args.option("dialect").value_or("auto");
    if (out.decoder.dialect != "auto" && !ctx.registry.find(out.decoder.dialect)) {
        std::string known;
        for (const Dialect *d : ctx.registry.dialects()) known += " " + std::string(d->id);
        std::fprintf(stderr, "gnss-cli: unknown dialect '%s' (known: auto%s)\n",
                     out.decoder.dialect.c_str(), known.c_str());
        return false;
    }
    out.decoder.lenient = args.flag("lenient");
    for (const auto &alias : args.options("alias")) {
        const auto eq = alias.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == alias.size()) {
            std::fprintf(stderr, "gnss-cli: --alias takes NEW=CANONICAL, e.g. PXYZW=PNMRX\n");
            return false;
        }
        out.decoder.addressAliases.emplace_back(alias.substr(0, eq), alias.substr(eq + 1));
    }
    if (const auto prefix = args.option("prefix")) {
        // --prefix NEW: the chosen dialect's renamable prefix was renamed to NEW on the receiver.
        const Dialect *d = ctx.registry.find(out.decoder.dialect);
        if (!d || d->renamablePrefix.empty()) {
            std::fprintf(stderr, "gnss-cli: --prefix needs --dialect with a renamable prefix "
                                 "(nemerix); use --alias NEW=CANONICAL otherwise\n");
            return false;
        }
        if (const std::string err = checkAddressPrefix(*prefix); !err.empty()) {
            std::fprintf(stderr, "gnss-cli: %s\n", err.c_str());
            return false;
        }
        out.decoder.addressAliases.emplace_back(*prefix, std::string(d->renamablePrefix));
    }
    out.json = args.flag("json");
    if (args.positionals().size() > 1) {
        std::fprintf(stderr, "gnss-cli: one input file at most (or - for standard input)\n");
        return false;
    }
    out.input = args.positionals().empty() ? "-" : args.positionals().front();
    return true;
}

bool run(const CommonOptions &opt, StreamDecoder &dec, StreamDecoder::Handler handler) {
    std::string error;
    const bool ok = readInput(
            opt.input, [&](std::string_view chunk) { dec.feed(chunk, handler); }, error);
    dec.finish();
    if (!ok) std::fprintf(stderr, "gnss-cli: %s\n", error.c_str());
    return ok;
}

} // namespace

int cmdDecode(const CliContext &ctx) {
    CommonOptions opt;
    if (!parseCommon(ctx, opt)) return 2;
    StreamDecoder dec(ctx.registry, opt.decoder);
    Output out;
    const bool ok = run(opt, dec, [&](const SentenceEvent &ev) {
        JsonWriter w(out.buffer());
        writeSentenceEventJson(w, ev);
        out.lineDone();
    });
    return ok ? 0 : 1;
}

int cmdEpochs(const CliContext &ctx) {
    CommonOptions opt;
    if (!parseCommon(ctx, opt)) return 2;
    StreamDecoder dec(ctx.registry, opt.decoder);
    EpochAssembler assembler(dec.dialect());
    Output out;
    auto onEpoch = [&](const Epoch &e) {
        JsonWriter w(out.buffer());
        e.writeJson(w);
        out.lineDone();
    };
    const bool ok = run(opt, dec, [&](const SentenceEvent &ev) {
        if (!ev.message) return;
        assembler.setDialect(dec.dialect());
        assembler.add(ev.sentence, *ev.message, onEpoch);
    });
    assembler.flush(onEpoch);
    return ok ? 0 : 1;
}

int cmdStats(const CliContext &ctx) {
    CommonOptions opt;
    if (!parseCommon(ctx, opt)) return 2;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    if (const auto t = ctx.args.option("threads")) {
        threads = static_cast<unsigned>(std::strtoul(t->c_str(), nullptr, 10));
        if (threads == 0 || threads > 64) {
            std::fprintf(stderr, "gnss-cli: --threads takes 1 to 64\n");
            return 2;
        }
    }
    const auto t0 = std::chrono::steady_clock::now();
    LogScanResult scan;
    bool ok = true;
    const MappedFile mapped(opt.input);
    if (!mapped.error().empty()) {
        std::fprintf(stderr, "gnss-cli: %s\n", mapped.error().c_str());
        ok = false;
    } else if (mapped.ok()) {
        // A regular file: decode it on every core (same counts as reading it front to back).
        scan = scanLog(mapped.data(), ctx.registry, opt.decoder, threads);
    } else {
        // A pipe or a terminal: one decoder, as the bytes come.
        StreamDecoder dec(ctx.registry, opt.decoder);
        EpochAssembler assembler(dec.dialect());
        auto onEpoch = [&](const Epoch &) { ++scan.epochs; };
        ok = run(opt, dec, [&](const SentenceEvent &ev) {
            if (!ev.message) return;
            assembler.setDialect(dec.dialect());
            assembler.add(ev.sentence, *ev.message, onEpoch);
        });
        assembler.flush(onEpoch);
        scan.framer = dec.framerStats();
        scan.addresses = dec.addressStats();
        scan.dialect = dec.dialect();
        scan.rtcm = dec.rtcmStats();
        scan.rtcmTypes = dec.rtcmTypes();
    }
    const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::uint64_t epochs = scan.epochs;
    struct {
        const FramerStats &framerStats() const { return s.framer; }
        const std::vector<AddressStats> &addressStats() const { return s.addresses; }
        const Dialect *dialect() const { return s.dialect; }
        const LogScanResult &s;
    } dec{scan};

    const FramerStats &fs = dec.framerStats();
    std::uint64_t sentences = 0, decoded = 0, errors = 0, unknown = 0, bad = 0, missing = 0,
                  rejected = 0;
    for (const auto &a : dec.addressStats()) {
        sentences += a.sentences;
        decoded += a.decoded;
        errors += a.decodeErrors;
        unknown += a.unknown;
        bad += a.checksumBad;
        missing += a.checksumMissing;
        rejected += a.rejected;
    }
    const double mb = static_cast<double>(fs.bytesIn) / 1e6;
    std::string o;
    if (opt.json) {
        JsonWriter w(o);
        w.beginObject().field("input", opt.input);
        // As summary names it: a log without vendor sentences is a standard NMEA one.
        w.field("dialect", dec.dialect() ? dec.dialect()->id : std::string_view("nmea"));
        w.field("bytes", fs.bytesIn).field("bytes_skipped", fs.bytesSkipped);
        // Skipped bytes that were RTCM 3 frames (a base interleaving them) are not junk.
        w.field("bytes_junk", scan.junkBytes());
        w.key("rtcm").beginObject().field("frames", scan.rtcm.frames);
        w.field("bytes", scan.rtcm.bytesInFrames).field("crc_failures", scan.rtcm.crcFailures);
        w.key("types").beginObject();
        for (const auto &[type, n] : scan.rtcmTypes) w.field(std::to_string(type), n);
        w.endObject().endObject();
        w.field("sentences", sentences).field("decoded", decoded).field("decode_errors", errors);
        w.field("unknown", unknown).field("checksum_bad", bad).field("checksum_missing", missing);
        w.field("rejected", rejected).field("truncated", fs.truncated);
        w.field("too_long", fs.tooLong).field("binary_aborted", fs.binaryAborted);
        w.field("epochs", epochs).field("seconds", seconds).field("threads", scan.threads);
        w.field("mb_per_s", seconds > 0 ? mb / seconds : 0.0);
        w.key("addresses").beginArray();
        for (const auto &a : dec.addressStats()) {
            w.beginObject().field("address", a.address).field("sentences", a.sentences);
            w.field("decoded", a.decoded).field("decode_errors", a.decodeErrors);
            w.field("unknown", a.unknown).field("checksum_bad", a.checksumBad);
            w.field("checksum_missing", a.checksumMissing).field("rejected", a.rejected);
            w.endObject();
        }
        w.endArray().endObject();
        o += '\n';
    } else {
        char line[256];
        std::snprintf(line, sizeof line, "%-12s %10s %10s %8s %8s %8s %8s\n", "address",
                      "sentences", "decoded", "errors", "unknown", "cs-bad", "cs-miss");
        o += line;
        for (const auto &a : dec.addressStats()) {
            std::snprintf(line, sizeof line, "%-12s %10llu %10llu %8llu %8llu %8llu %8llu\n",
                          a.address.c_str(), (unsigned long long)a.sentences,
                          (unsigned long long)a.decoded, (unsigned long long)a.decodeErrors,
                          (unsigned long long)a.unknown, (unsigned long long)a.checksumBad,
                          (unsigned long long)a.checksumMissing);
            o += line;
        }
        std::snprintf(line, sizeof line, "%-12s %10llu %10llu %8llu %8llu %8llu %8llu\n", "total",
                      (unsigned long long)sentences, (unsigned long long)decoded,
                      (unsigned long long)errors, (unsigned long long)unknown,
                      (unsigned long long)bad, (unsigned long long)missing);
        o += line;
        std::snprintf(line, sizeof line,
                      "\ndialect: %s\nbytes: %llu (skipped %llu)\nlines truncated: %llu, too long: "
                      "%llu, binary aborted: %llu\nrejected by checksum policy: %llu\nepochs: "
                      "%llu\n",
                      dec.dialect() ? std::string(dec.dialect()->id).c_str()
                                    : "nmea (no vendor sentences)",
                      (unsigned long long)fs.bytesIn, (unsigned long long)fs.bytesSkipped,
                      (unsigned long long)fs.truncated, (unsigned long long)fs.tooLong,
                      (unsigned long long)fs.binaryAborted, (unsigned long long)rejected,
                      (unsigned long long)epochs);
        o += line;
        if (scan.rtcm.frames) {
            // "RTCM 3: 610 frames, 45210 bytes (1005 x10, 1077 x600); junk: 0 bytes"
            std::string types;
            for (const auto &[type, n] : scan.rtcmTypes)
                types += (types.empty() ? "" : ", ") + std::to_string(type) + " x" +
                         std::to_string(n);
            o += "RTCM 3: " + std::to_string(scan.rtcm.frames) + " frames, " +
                 std::to_string(scan.rtcm.bytesInFrames) + " bytes (" + types +
                 "); junk: " + std::to_string(scan.junkBytes()) + " bytes\n";
        }
        std::snprintf(line, sizeof line,
                      "time: %.3f s (%.0f MB/s, %.0f sentences/s, %u thread%s)\n", seconds,
                      seconds > 0 ? mb / seconds : 0.0,
                      seconds > 0 ? static_cast<double>(sentences) / seconds : 0.0, scan.threads,
                      scan.threads == 1 ? "" : "s");
        o += line;
    }
    std::fwrite(o.data(), 1, o.size(), stdout);
    return ok ? 0 : 1;
}

} // namespace gnss::cli
