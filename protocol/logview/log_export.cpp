#include "logview/log_export.h"

#include "logview/log_time.h"

#include <cmath>
#include <cstdio>

namespace gnss::logview {
namespace {

// Buffers output and hands it to the sink in 1 MB pieces.
class Out {
public:
    explicit Out(const ExportSink &sink) : sink_(sink) { buf_.reserve(1 << 20); }
    Out &operator<<(std::string_view s) {
        buf_ += s;
        if (buf_.size() >= (1 << 20)) flush();
        return *this;
    }
    Out &num(double v, const char *fmt) {
        char b[48];
        std::snprintf(b, sizeof b, fmt, v);
        return *this << b;
    }
    bool flush() {
        if (ok_ && !buf_.empty()) ok_ = sink_(buf_);
        buf_.clear();
        return ok_;
    }
    bool ok() const { return ok_; }

private:
    const ExportSink &sink_;
    std::string buf_;
    bool ok_ = true;
};

// The length of the UTF-8 sequence at the start of `s` when it is a character XML 1.0 allows
// (well formed, no surrogate, not U+FFFE or U+FFFF), else 0.
std::size_t xmlCharLength(std::string_view s) {
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    const unsigned char c = b(0);
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF; // the second byte's range
    if (c < 0x80) return c >= 0x20 || c == '\t' || c == '\n' || c == '\r' ? 1 : 0;
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        if (c == 0xE0) lo = 0xA0;
        if (c == 0xED) hi = 0x9F; // no surrogates
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        if (c == 0xF0) lo = 0x90;
        if (c == 0xF4) hi = 0x8F;
    } else
        return 0;
    if (s.size() < n || b(1) < lo || b(1) > hi) return 0;
    for (std::size_t i = 2; i < n; ++i)
        if (b(i) < 0x80 || b(i) > 0xBF) return 0;
    if (n == 3 && c == 0xEF && b(1) == 0xBF && b(2) >= 0xBE) return 0; // U+FFFE, U+FFFF
    return n;
}

// Text for an XML element: markup escaped, and what XML cannot hold (control bytes, bytes that
// are no UTF-8: a file name may be anything) replaced by U+FFFD, so the document stays well
// formed whatever the log is called.
std::string xmlEscape(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t n = xmlCharLength(s.substr(i));
        if (n == 0) {
            out += "\xEF\xBF\xBD";
            ++i;
            continue;
        }
        switch (s[i]) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out.append(s.substr(i, n));
        }
        i += n;
    }
    return out;
}

std::string_view gpxFix(FixType f) {
    switch (f) {
    case FixType::Fix2D: return "2d";
    case FixType::Fix3D: return "3d";
    case FixType::Dgnss:
    case FixType::RtkFloat:
    case FixType::RtkFixed: return "dgps";
    case FixType::None: return "none";
    default: return {};
    }
}

// KML colours are aabbggrr.
std::string kmlColour(FixType f) {
    const std::string_view rgb = fixColour(f);
    std::string out = "ff";
    out += rgb.substr(5, 2);
    out += rgb.substr(3, 2);
    out += rgb.substr(1, 2);
    return out;
}

} // namespace

std::optional<ExportFormat> exportFormatFromName(std::string_view n) {
    if (n == "gpx") return ExportFormat::Gpx;
    if (n == "kml") return ExportFormat::Kml;
    if (n == "csv") return ExportFormat::Csv;
    if (n == "nmea") return ExportFormat::Nmea;
    return std::nullopt;
}

std::string_view fixColour(FixType f) {
    switch (f) {
    case FixType::None: return "#9E9E9E";      // grey
    case FixType::Estimated: return "#7B1FA2"; // purple
    case FixType::Fix2D: return "#FFB300";     // amber
    case FixType::Fix3D: return "#1E88E5";     // blue
    case FixType::Dgnss: return "#00897B";     // teal
    case FixType::RtkFloat: return "#FB8C00";  // orange
    case FixType::RtkFixed: return "#43A047";  // green
    case FixType::Manual:
    case FixType::Simulator: return "#424242"; // dark grey
    }
    return "#9E9E9E";
}

bool writeGpx(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
              const std::string &name, const ExportSink &sink) {
    Out o(sink);
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<gpx version=\"1.1\" creator=\"GNSS Workbench\" "
         "xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
         "  <trk>\n    <name>"
      << xmlEscape(name) << "</name>\n    <trkseg>\n";
    for (std::uint64_t i = first; i <= last && i < records.size() && o.ok(); ++i) {
        const EpochRecord &r = records[i];
        if (!r.hasPosition()) continue;
        o << "      <trkpt lat=\"";
        o.num(r.lat, "%.9f") << "\" lon=\"";
        o.num(r.lon, "%.9f") << "\">";
        if (!std::isnan(r.altMsl)) o.num(r.altMsl, "<ele>%.3f</ele>");
        if (r.has(kDateKnown)) o << "<time>" << formatUtcMs(r.utcMs) << "</time>";
        if (const auto f = gpxFix(r.fixType()); !f.empty()) o << "<fix>" << f << "</fix>";
        if (r.sats != 255) o << "<sat>" << std::to_string(r.sats) << "</sat>";
        if (!std::isnan(r.hdop)) o.num(r.hdop, "<hdop>%.2f</hdop>");
        o << "</trkpt>\n";
    }
    o << "    </trkseg>\n  </trk>\n</gpx>\n";
    return o.flush();
}

bool writeKml(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
              const std::string &name, const ExportSink &sink) {
    Out o(sink);
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<kml xmlns=\"http://www.opengis.net/kml/2.2\">\n<Document>\n  <name>"
      << xmlEscape(name) << "</name>\n";
    for (int f = 0; f <= static_cast<int>(FixType::Simulator); ++f) {
        const auto fix = static_cast<FixType>(f);
        o << "  <Style id=\"fix_" << toString(fix) << "\"><LineStyle><color>" << kmlColour(fix)
          << "</color><width>3</width></LineStyle></Style>\n";
    }
    bool open = false;
    FixType runFix = FixType::None;
    std::uint64_t runFirst = 0;
    auto close = [&] {
        if (open) o << "\n      </coordinates>\n    </LineString>\n  </Placemark>\n";
        open = false;
    };
    for (std::uint64_t i = first; i <= last && i < records.size() && o.ok(); ++i) {
        const EpochRecord &r = records[i];
        if (!r.hasPosition()) continue;
        if (!open || r.fixType() != runFix) {
            close();
            runFix = r.fixType();
            runFirst = i;
            o << "  <Placemark>\n    <name>" << fixWords(runFix) << "</name>\n"
              << "    <description>from epoch " << std::to_string(runFirst);
            if (r.hasTime()) o << " (" << formatTime(r) << ")";
            o << "</description>\n    <styleUrl>#fix_" << toString(runFix)
              << "</styleUrl>\n    <LineString>\n      <tessellate>1</tessellate>\n"
                 "      <altitudeMode>clampToGround</altitudeMode>\n      <coordinates>";
            open = true;
        }
        o << "\n        ";
        o.num(r.lon, "%.9f") << ",";
        o.num(r.lat, "%.9f");
        if (!std::isnan(r.altMsl)) o.num(r.altMsl, ",%.3f");
    }
    close();
    o << "</Document>\n</kml>\n";
    return o.flush();
}

bool writeCsv(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
              std::uint64_t end, const ExportSink &sink) {
    Out o(sink);
    o << "epoch,time,host_time,fix,lat,lon,alt_msl,sats_used,hdop,mean_snr,speed_mps,station,"
         "offset,length,flags\r\n";
    auto opt = [&](bool has, double v, const char *fmt) {
        o << ",";
        if (has) o.num(v, fmt);
    };
    for (std::uint64_t i = first; i <= last && i < records.size() && o.ok(); ++i) {
        const EpochRecord &r = records[i];
        o << std::to_string(i) << "," << formatTime(r) << ",";
        if (r.hostMs != kNoTime) o << formatUtcMs(r.hostMs);
        o << "," << toString(r.fixType());
        opt(r.hasPosition(), r.lat, "%.9f");
        opt(r.hasPosition(), r.lon, "%.9f");
        opt(!std::isnan(r.altMsl), r.altMsl, "%.3f");
        opt(r.sats != 255, r.sats, "%.0f");
        opt(!std::isnan(r.hdop), r.hdop, "%.2f");
        opt(r.snr != 255, r.snr, "%.0f");
        opt(!std::isnan(r.speed), r.speed, "%.3f");
        opt(r.station >= 0, r.station, "%.0f");
        o << "," << std::to_string(r.offset) << ",";
        const std::uint64_t next = i + 1 < records.size() ? records[i + 1].offset : end;
        if (next >= r.offset) o << std::to_string(next - r.offset);
        o << ",";
        static constexpr std::pair<EpochFlag, const char *> kNames[] = {
                {kGapBefore, "gap"},
                {kLinkGap, "link_gap"},
                {kTimeBack, "time_back"},
                {kMidnight, "midnight"},
                {kChecksumErrors, "checksum"},
                {kDecodeErrors, "decode_error"},
                {kJunk, "junk"},
                {kTruncatedLines, "cut_lines"},
                {kFixChange, "fix_change"},
                {kDialectChange, "dialect_change"},
                {kTimeMark, "time_mark"},
                {kJammingChange, "jamming_change"},
                {kStationChange, "station_change"}};
        bool firstFlag = true;
        for (const auto &[flag, text] : kNames)
            if (r.has(flag)) {
                if (!firstFlag) o << " ";
                o << text;
                firstFlag = false;
            }
        o << "\r\n";
    }
    return o.flush();
}

} // namespace gnss::logview
