#pragma once
// Export of a log or a range of its epochs: GPX 1.1, KML (the track coloured by fix type, in the
// views' fix colours), CSV (one row per epoch, docs/export.md) and the NMEA bytes exactly as they
// are in the file. Written through a sink in pieces, so a whole log never sits in memory twice.
#include "logview/epoch_record.h"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gnss::logview {

enum class ExportFormat { Gpx, Kml, Csv, Nmea };
std::optional<ExportFormat> exportFormatFromName(std::string_view name); // gpx, kml, csv, nmea

using ExportSink = std::function<bool(std::string_view)>; // false: stop (a write failed)

// GPX 1.1: one track, one segment, a trkpt per epoch with a position: ele (metres above mean sea
// level), time (when the date is known), fix (none/2d/3d/dgps: RTK and DGNSS are "dgps"), sat,
// hdop.
bool writeGpx(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
              const std::string &name, const ExportSink &sink);
// KML 2.2: a LineString per run of epochs with the same fix type, styled with the fix colour,
// and a folder per fix type; altitude clamped to the ground (heights in the description).
bool writeKml(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
              const std::string &name, const ExportSink &sink);
// CSV with a header (docs/export.md): every epoch, positioned or not.
// `end` is the file offset where the last record ends (for its length).
bool writeCsv(std::span<const EpochRecord> records, std::uint64_t first, std::uint64_t last,
              std::uint64_t end, const ExportSink &sink);

// The colour of a fix type, "#RRGGBB": the same as the views' fix badge (ui/style).
std::string_view fixColour(FixType f);

} // namespace gnss::logview
