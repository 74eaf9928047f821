#include "cli/command_table.h"

#include "core/baud_rates.h"

#include <algorithm>

namespace gnss::cli {
namespace {

// Options shared by several commands, so their words agree everywhere.
constexpr OptionSpec kDialect{"dialect", "D",
                              "the receiver's dialect: auto (the default: recognised from the "
                              "stream) or one of the dialects below"};
constexpr OptionSpec kLenient{"lenient", "",
                              "decode sentences whose checksum is wrong or missing, and mark them"};
constexpr OptionSpec kAlias{"alias", "NEW=CANONICAL",
                            "read a renamed proprietary prefix, e.g. PXYZW=PNMRX (repeatable)"};
constexpr OptionSpec kPrefix{"prefix", "NEW",
                             "with --dialect D: the dialect's renamable prefix (below) was renamed "
                             "NEW on the receiver"};
constexpr OptionSpec kPort{"port", "P", "serial port: ttyUSB0, /dev/ttyACM0 or any path to a tty"};
constexpr OptionSpec kTcp{"tcp", "HOST:PORT",
                          "a TCP source: a serial-to-Ethernet server, gnss-sim --tcp"};
constexpr OptionSpec kGpsd{"gpsd", "HOST[:PORT][/DEVICE]",
                           "a receiver that gpsd holds, read through gpsd (port 2947 and every "
                           "device when left out); read only: gpsd owns the port"};
constexpr OptionSpec kDuration{"duration", "S", "stop after S seconds"};
constexpr OptionSpec kReferenceSite{"reference-site", "NAME",
                                    "instead of --reference: a site of the list (gnss-cli sites), "
                                    "its antenna height added; a unique prefix will do"};

constexpr OptionSpec kDecodeOptions[] = {kDialect, kLenient, kAlias, kPrefix};
constexpr OptionSpec kStatsOptions[] = {
        kDialect,
        kLenient,
        kAlias,
        kPrefix,
        {"json", "", "one JSON object instead of the table"},
        {"threads", "N", "decode a file on N threads, 1 to 64 (default: one per core)"},
};
constexpr OptionSpec kEncodeOptions[] = {
        {"query", "", "the sentences that read the KEYs back instead"},
        {"prefix", "NEW", "write the dialect's renamable prefix (below) as NEW"},
};
// The sources every link command takes (cli_source.h), in the same words everywhere.
constexpr OptionSpec kSim{"sim", "D", "a built-in simulated receiver of one of the dialects below"};
constexpr OptionSpec kReplay{"replay", "FILE", "a recorded log, at its recorded pace"};
constexpr OptionSpec kLinkBaud{"baud", "B", "line speed (default: detected)"};
constexpr OptionSpec kSpeed{"speed", "X", "replay X times faster (below 1: slower)"};
constexpr OptionSpec kFast{"fast", "", "replay without waiting"};

constexpr OptionSpec kProbeOptions[] = {kPort, kTcp, kGpsd, kSim, kLinkBaud};
constexpr OptionSpec kMonitorOptions[] = {
        kPort,
        kTcp,
        kGpsd,
        kReplay,
        kSim,
        kLinkBaud,
        kDialect,
        kLenient,
        {"epochs", "", "one JSON object per navigation epoch instead of per sentence"},
        kDuration,
        kSpeed,
        kFast,
};
constexpr OptionSpec kRecordOptions[] = {
        kPort,     kTcp,
        kGpsd,     kSim,
        kLinkBaud, {"out", "FILE", "write the bytes received to FILE, their index to FILE.idx"},
        kDuration,
};
constexpr OptionSpec kTtffOptions[] = {
        kPort,
        kTcp,
        kSim,
        kLinkBaud,
        {"start", "cold|warm|hot", "a kind of start to measure (repeatable, run in that order)"},
        {"runs", "N", "restarts of each kind (default 10)"},
        {"timeout", "S", "a run that has no 3D fix after S seconds is a timeout (default 180)"},
        {"pause", "S", "seconds between runs (default 5)"},
        {"hold", "S", "before a warm or hot start, a 3D fix held S seconds (default 30)"},
        {"reference", "LAT,LON[,HEIGHT]",
         "the first fix's distance, and the accuracy between runs, from this point (degrees, "
         "ellipsoidal metres)"},
        kReferenceSite,
        {"limit", "START:STAT<=S",
         "a limit to pass, e.g. cold:mean<=60 (STAT: mean, median, p90, p95, max; repeatable)"},
        {"report", "FILE",
         "write the report as PDF or HTML by FILE's extension, and the runs beside it as CSV "
         "and JSON"},
        {"lang", "en|ru", "the report's language (default: the system's)"},
        {"units", "metric|imperial", "the report's lengths in metres or feet (default metric)"},
        {"json", "", "one JSON object at the end instead of a line per run and a table"},
};
constexpr OptionSpec kSendOptions[] = {
        kPort,
        kTcp,
        kSim,
        kLinkBaud,
        {"dialect", "D",
         "whose reply rules to wait by: auto (default) or one of the dialects below"},
        {"timeout", "S", "seconds to wait for each reply (default: the dialect's rule)"},
        {"fix-checksum", "",
         "replace a wrong checksum typed in a SENTENCE (and say so) rather than refuse it"},
};
constexpr OptionSpec kConfigOptions[] = {
        kPort,
        kTcp,
        kSim,
        kLinkBaud,
        {"dialect", "D", "the receiver's dialect (default: identified by its probe)"},
};
constexpr OptionSpec kCompareOptions[] = {
        {"port", "P", "a receiver on a serial port (repeatable; its speed is detected)"},
        {"tcp", "HOST:PORT", "a receiver over TCP (repeatable)"},
        {"gpsd", "HOST[:PORT][/DEVICE]", "a receiver that gpsd holds (repeatable)"},
        {"sim", "D", "a built-in simulated receiver of one of the dialects below (repeatable)"},
        {"duration", "S", "with a live source: stop after S seconds (default: Ctrl-C)"},
        {"json", "", "one JSON object at the end instead of a line per matched epoch"},
        kDialect,
        kLenient,
};
constexpr OptionSpec kNtripOptions[] = {
        {"caster", "HOST:PORT", "the NTRIP caster"},
        {"mount", "M", "the mountpoint whose corrections to receive"},
        {"sourcetable", "", "print the caster's source table (one JSON object per entry)"},
        {"nearest", "", "receive from the nearest RTCM 3 mountpoint (needs a position)"},
        {"user", "U", "user name for the caster"},
        {"password-env", "VAR", "read the password from environment variable VAR"},
        {"ntrip-version", "1|2", "NTRIP revision (default 2)"},
        {"gga", "auto|LAT,LON,H", "the position sent to casters that ask for one"},
        {"out", "FILE", "write the raw RTCM received to FILE"},
        kDuration,
        {"quiet", "", "no JSON lines (with --out)"},
        kPort,
        kTcp,
        kSim,
        kLinkBaud,
};
constexpr OptionSpec kServeOptions[] = {
        kPort,
        {"baud", "B", "line speed of --port (default: detected)"},
        kTcp,
        kSim,
        {"replay", "FILE", "a recorded file, served at its own pace from the first client on"},
        {"loop", "", "with --replay: start again at the end"},
        {"ntrip", "[ADDR:]PORT/MOUNT",
         "an NTRIP caster (revision 1 and 2) with mountpoint MOUNT: the source's RTCM 3 frames "
         "(ADDR: 127.0.0.1 when left out; PORT 0: a free one)"},
        {"user", "U", "the caster's user name (the mountpoint then needs a password)"},
        {"password-env", "VAR", "read the caster's password from environment variable VAR"},
        {"raw", "[ADDR:]PORT", "the source's bytes, exactly, to every client of this TCP port"},
        kDuration,
};

// The log viewer's commands (export, summary, play): the range and the decoding.
constexpr OptionSpec kFrom{"from", "T",
                           "start at the first epoch at or after T: a UTC time "
                           "(2024-03-15T10:00:00Z), a time of day (10:00:00) or an epoch (#120)"};
constexpr OptionSpec kTo{"to", "T", "end with the last epoch at or before T (as --from)"};
constexpr OptionSpec kExportOptions[] = {
        {"format", "gpx|kml|csv|nmea", "what to write (docs/export.md)"}, kFrom,    kTo,
        {"out", "OUT", "the file to write (- for standard output)", 'o'}, kDialect, kLenient,
};
constexpr OptionSpec kSummaryOptions[] = {
        {"json", "", "one JSON object instead of the text"},
        kFrom,
        kTo,
        kDialect,
        kLenient,
        {"reference", "LAT,LON[,HEIGHT]",
         "accuracy against this point (degrees; ellipsoidal metres; horizontal only without)"},
        kReferenceSite,
};
constexpr OptionSpec kSitesOptions[] = {
        {"json", "", "list: the list as one JSON object (the export format)"},
        {"llh", "LAT,LON[,HEIGHT]",
         "add: the position (degrees, metres above the ellipsoid; the mark's, not the antenna's)"},
        {"ecef", "X,Y,Z", "add: the position as Earth-centred, Earth-fixed metres"},
        {"antenna-height", "H", "add: metres from the mark up to the antenna reference point"},
        {"accuracy", "M", "add: how well the position is known, metres (e.g. horizontal sigma)"},
        {"date", "YYYY-MM-DD", "add: when it was obtained (default: today, UTC)"},
        {"method", "TEXT", "add: how it was obtained: known (default), survey-in, ppp, ..."},
        {"note", "TEXT", "add: a note"},
        {"replace", "", "add, import: replace a site of the same name"},
};
constexpr OptionSpec kBaseOptions[] = {
        kPort,
        kTcp,
        kSim,
        kLinkBaud,
        {"dialect", "D", "the receiver's dialect (default: identified by its probe)"},
        {"ecef", "X,Y,Z",
         "set: the antenna reference point (or the mark, with --antenna-height), "
         "Earth-centred, Earth-fixed metres"},
        {"llh", "LAT,LON,HEIGHT",
         "set: the mark: degrees (decimal, DM or DMS, N/S/E/W or a sign) and metres above the "
         "ellipsoid"},
        {"msl", "",
         "set: --llh's HEIGHT is above sea level (the receiver's geoid separation is "
         "added)"},
        {"site", "NAME", "set: a site of the list (gnss-cli sites), its antenna height included"},
        {"antenna-height", "H", "set: metres from the mark up to the antenna reference point"},
        {"station", "N", "set, survey --set: the RTCM station id"},
        {"rtcm-port", "N",
         "set, survey --set: the receiver's port that sends the RTCM 3 (1 = COM1)"},
        {"rtcm-baud", "B", "that port's speed (default: as it is, else the receiver's default)"},
        {"rtcm-interval", "S", "set, survey --set: seconds between the observables"},
        {"save", "", "set: save the settings to the receiver's flash once verified"},
        {"minutes", "M", "survey: average for M minutes"},
        {"sigma", "METRES", "survey: average until the mean's accuracy is METRES (3D)"},
        {"by-receiver", "", "survey: the receiver averages its own position (whole --minutes)"},
        {"input", "V", "survey --by-receiver: which fixes it averages (a value of its schema)"},
        {"save-site", "NAME", "survey: save the result as a site of the list"},
        {"set", "", "survey: then set the base at the result (with the set options)"},
};
constexpr OptionSpec kPlayOptions[] = {
        {"pty", "", "play to a new pseudo-terminal (its path is printed on standard output)"},
        {"tcp", "PORT", "play to TCP clients on 127.0.0.1:PORT (starts with the first client)"},
        kPort,
        {"baud", "B", "with --port: line speed (default 9600)"},
        {"speed", "X", "play X times faster (below 1: slower)"},
        {"loop", "", "start again at the end"},
        kFrom,
        kTo,
        kDialect,
        kLenient,
};

// `details` is one paragraph per line, wrapped at 80 columns when printed; a paragraph that
// starts with spaces is a list item, continued under its text.
constexpr CommandSpec kCommands[] = {
        {"decode", cmdDecode, "decode [--dialect D] [--lenient] [FILE|-]",
         "one JSON object per sentence of a log", kDecodeOptions,
         "Decodes FILE (or standard input: - or nothing) and prints one JSON object per sentence "
         "on standard output (JSON Lines): line, address, talker, type, checksum, and data or "
         "error. Bad input is skipped and counted, never fatal.\n"
         "Exit status: 0 the input was read to its end, 1 it could not be read, 2 usage error.\n"},
        {"epochs", cmdEpochs, "epochs [--dialect D] [--lenient] [FILE|-]",
         "one JSON object per navigation epoch", kDecodeOptions,
         "Prints one JSON object per navigation epoch (the sentences sharing one fix time): "
         "time, fix, lat, lon, altitudes, dilutions, speed, course, DGPS age and the satellites "
         "with their signals.\n"
         "Exit status: 0 the input was read to its end, 1 it could not be read, 2 usage error.\n"},
        {"stats", cmdStats, "stats [--dialect D] [--lenient] [--json] [--threads N] [FILE|-]",
         "vet a log: counts per address, errors, speed", kStatsOptions,
         "Decodes every sentence and prints, per address, sentences, decoded, decode errors, "
         "unknown, checksum bad and missing; then bytes read and skipped, lines truncated or too "
         "long, epochs, the dialect recognised and the decoding speed. A regular file is decoded "
         "on every core with the same counts as one front-to-back pass.\n"
         "Exit status: 0 the input was read to its end, 1 it could not be read, 2 usage error.\n"},
        {"export", cmdExport, "export --format gpx|kml|csv|nmea [--from T] [--to T] FILE|- -o OUT",
         "a log or a range of it as GPX, KML, CSV or its NMEA bytes", kExportOptions,
         "Indexes FILE (any NMEA log, a recording, a .gz log; - reads standard input whole first) "
         "and writes the epochs from --from to "
         "--to: GPX 1.1 (a track point per epoch with a position: time, ele, fix, sat, hdop), "
         "KML (the track coloured by fix type), CSV (one row per epoch, columns in "
         "docs/export.md) or nmea (the bytes of those epochs exactly as they are in FILE).\n"
         "Exit status: 0 written, 1 FILE unreadable or OUT not writable, 2 usage error.\n"},
        {"summary", cmdSummary,
         "summary [--json] [--from T] [--to T] [--reference LAT,LON[,HEIGHT] | --reference-site "
         "NAME] FILE|-",
         "what a log holds: duration, fix availability, gaps, CEP, events", kSummaryOptions,
         "Indexes FILE (- reads standard input whole first) and prints its duration, epochs, "
         "availability per fix type, gaps, time "
         "jumps, time to first fix and to RTK fixed, CEP50/CEP95/2DRMS of the stationary part "
         "(speed under 0.5 m/s; every position when no speed is known), the largest HDOP and "
         "the events (fix changes, gaps, resets, checksum-error bursts, dialect changes, time "
         "marks, jamming, base station changes). --json prints one JSON object.\n"
         "With --reference, the positions against that point too: the bias east, north and up "
         "(mean position minus the point), the horizontal error (mean, median, R95, 2DRMS; "
         "CEP50/CEP95 about the mean position), the vertical error (mean, median, 95 %; only "
         "with a HEIGHT and a receiver that gives its geoid separation) and the share of "
         "epochs within 2 cm, 10 cm, 50 cm, 1 m, 2 m and 5 m, overall and per fix type; in "
         "JSON the \"reference\" object. --reference-site NAME takes the point from the site "
         "list (gnss-cli sites): the site's position with its antenna height added, where the "
         "receiver's antenna is.\n"
         "Exit status: 0 done, 1 FILE unreadable, 2 usage error or an unknown or ambiguous "
         "site.\n"},
        {"play", cmdPlay,
         "play FILE|- --pty|--tcp PORT|--port P [--speed X] [--loop] [--from T] [--to T]",
         "play a log out at its own pace, like gpsfake", kPlayOptions,
         "Sends the bytes of FILE (- reads standard input whole first), or of its epochs from "
         "--from to --to, exactly as they are, "
         "each epoch when it is due: at the pace of the recording's host times (FILE.idx) when "
         "there are some, else of the epochs' UTC times (a reset's step back and missing times "
         "add no wait); --speed X plays X times faster. --pty prints the new pseudo-terminal's "
         "path and ends when its reader closes it; --tcp listens on 127.0.0.1 and starts with "
         "the first client; --port writes to a serial port.\n"
         "Exit status: 0 played to the end (or the reader left), 1 FILE or the output cannot be "
         "opened, 2 usage error, 130 interrupted.\n"},
        {"schema",
         cmdSchema,
         "schema DIALECT",
         "a dialect's settings schema as JSON",
         {},
         "Prints the settings schema of DIALECT (one of those below) as one JSON array: "
         "key, label, group, type, default, unit, min/max or options, access, read_back, write, "
         "help.\n"
         "Exit status: 0 printed, 2 unknown dialect.\n",
         1},
        {"encode", cmdEncode,
         "encode DIALECT KEY=VALUE...\n"
         "encode DIALECT --query KEY...",
         "the sentences that set (or read back) settings", kEncodeOptions,
         "Prints the sentences, with checksums, that set the given settings, one per line; with "
         "--query the sentences that read them back. KEY is a schema key (rtk.PVTRATE) or the "
         "spec's own name (PVTRATE); gnss-cli schema DIALECT lists them.\n"
         "Exit status: 0 printed, 2 usage error, an unknown KEY or a value the schema refuses (out "
         "of range, not an option): nothing is printed.\n"},
        {"ports",
         cmdPorts,
         "ports",
         "the serial ports, one JSON object each",
         {},
         "Prints one JSON object per serial port: port, location, description, manufacturer, "
         "serial_number, usb_id (VID:PID, empty when not USB).\n"
         "Exit status: 0 listed, 2 usage error.\n",
         0},
        {"probe", cmdProbe,
         "probe --port P [--baud B] | --tcp HOST:PORT | --gpsd HOST[:PORT][/DEVICE] | --sim D",
         "detect a receiver's baud, dialect, model and firmware", kProbeOptions,
         "Finds the speed (the --baud given first, then {detection order}: the first giving two "
         "valid sentences), then the receiver (its "
         "proprietary sentences, then each dialect's probe), and prints one JSON object: port, "
         "baud, dialect, dialect_name, model, firmware, method, reply, tried (bytes and "
         "sentences per rate) and error. Through gpsd no probe can be sent: the receiver is known "
         "by its own sentences only.\n"
         "Exit status: 0 found, 1 nothing found or the port cannot be opened, 2 usage error or a "
         "device gpsd does not have, 130 interrupted.\n",
         0},
        {"monitor", cmdMonitor,
         "monitor --port P|--tcp HOST:PORT|--gpsd HOST[:PORT][/DEVICE]|--replay FILE|--sim D "
         "[OPTIONS]",
         "decode a live receiver, a TCP source or a replayed log", kMonitorOptions,
         "Decodes live: one JSON object per sentence as decode prints, or per epoch with --epochs "
         "as epochs prints. A lost serial, TCP or gpsd link is reported on standard error and "
         "retried. "
         "Runs until --duration, the end of a replay, or Ctrl-C. Several sources (the source "
         "options repeated: --port A --port B --sim nvs) are monitored at once, each line "
         "starting with receiver (its place among them, from 0) and source (as given).\n"
         "Exit status: 0 ended by --duration or the end of the replay, 1 the source cannot be "
         "opened or sent nothing within --duration, 2 usage error or a device gpsd does not "
         "have, 130 interrupted (Ctrl-C; 143 for SIGTERM).\n",
         0},
        {"record", cmdRecord,
         "record --port P|--tcp HOST:PORT|--gpsd HOST[:PORT][/DEVICE]|--sim D --out FILE "
         "[OPTIONS]",
         "record a receiver to FILE and FILE.idx", kRecordOptions,
         "Writes FILE (exactly the bytes received) and FILE.idx (when they came, gaps). A lost "
         "link is retried and the recording goes on in the same files with a gap mark. Runs "
         "until --duration or Ctrl-C; the files are flushed and closed either way. With several "
         "sources (the source options repeated), --out names a folder and each receiver's "
         "recording in it is named after its source (ttyUSB0.nmea, sim_nvs.nmea).\n"
         "Exit status: 0 ended by --duration, 1 the source or FILE cannot be opened or nothing was "
         "received within --duration, 2 usage error or a device gpsd does not have, 130 "
         "interrupted (Ctrl-C; 143 for SIGTERM).\n",
         0},
        {"send", cmdSend, "send --port P|--tcp HOST:PORT|--sim D [OPTIONS] SENTENCE...",
         "send commands, print replies and outcomes", kSendOptions,
         "Sends each SENTENCE in turn ($ and checksum added when missing; a wrong checksum is "
         "refused unless --fix-checksum), waits for its reply as "
         "the dialect's reply rules say, retries on silence, and prints one JSON object per "
         "command: sentence, outcome (accepted, refused, timed out, link lost, sent, failed), "
         "detail, attempts, ms, replies, and baud after a baud change. What is sent (> ...) and "
         "received (< ...) is echoed on standard error. Every SENTENCE is checked before the "
         "port is opened: an address of upper-case letters and digits, no character NMEA does "
         "not allow or reserves, a right checksum.\n"
         "Exit status: 0 every command accepted, 1 any refused, timed out or failed, or the "
         "source cannot be opened, 2 usage error or a malformed SENTENCE, 130 interrupted.\n"},
        {"config", cmdConfig,
         "config --port P|--tcp HOST:PORT|--sim D [--baud B] [--dialect D] get [KEY...]\n"
         "config ... set KEY=VALUE...\n"
         "config ... export FILE | apply FILE | diff FILE\n"
         "config ... action save|defaults|cold|warm|hot",
         "read, set, export, apply or compare a receiver's settings", kConfigOptions,
         "The settings engine of the GUI's settings dock. Without --baud the speed is detected, "
         "without --dialect the receiver is identified.\n"
         "  get     one JSON object: dialect, model, firmware, values, write_only\n"
         "  set     reads the KEYs, sends what differs in a safe order, reads back: one JSON "
         "line per command, one per setting with its verdict, then a summary\n"
         "  export  reads everything and writes a versioned JSON profile to FILE\n"
         "  apply   applies the difference between FILE and the receiver, as set does\n"
         "  diff    one JSON line per setting whose value in FILE differs\n"
         "  action  save to flash, restore the defaults, or restart (cold, warm, hot)\n"
         "Exit status: 0 done (diff: no difference), 1 a command refused or failed, a value that "
         "did not verify, the port or FILE cannot be opened, (diff) differences, 2 usage error, "
         "an unknown setting, a value out of range, an action the receiver does not have, a "
         "profile that is malformed or for another dialect or model (nothing sent).\n"},
        {"rtcm",
         cmdRtcm,
         "rtcm [FILE|-]",
         "an RTCM 3 stream as JSON, counts on stderr",
         {},
         "Prints one JSON object per RTCM 3 frame whose CRC-24Q is right, on standard output, "
         "and at the end one summary object (frames, bytes, bytes skipped, CRC failures, frames "
         "per message type) on standard error. Bytes outside frames are skipped.\n"
         "Exit status: 0 the input was read to its end, 1 it could not be read, 2 usage error.\n"},
        {"ttff", cmdTtff,
         "ttff --port P|--tcp HOST:PORT|--sim D --start cold|warm|hot [--start ...] [--runs N] "
         "[OPTIONS]",
         "a time-to-first-fix campaign: N restarts of each kind, their statistics", kTtffOptions,
         "Restarts the receiver N times for each --start with its dialect's own command "
         "($PNVGRST,F or W; CSTART, WSTART, HSTART; $PNMRX111,COLD, WARM or HOT: never a "
         "sticky bit) and measures on this computer's clock, from the moment the command is "
         "written, the time to the first position, to 2D and to 3D (the TTFF, as datasheets "
         "state it) and, when the receiver reports them, to DGNSS, RTK float and RTK fixed. "
         "Before a warm or hot start the receiver holds a 3D fix --hold seconds (its "
         "ephemerides). A start the receiver does not have is refused before anything is "
         "sent, naming those it has. A run without a fix after --timeout is counted as a "
         "timeout, and so is a warm or hot run whose receiver gives no fix to hold by then (its "
         "restart not sent); a link lost during a run marks it lost, and the campaign goes on once "
         "the "
         "link is back. Progress goes to standard error; a line per run, then per kind of "
         "start the runs, fixes, timeouts and the TTFF's mean, median, p90, p95, min and max. "
         "With --json one object: starts (cold/warm/hot: runs, fixed, timeouts, lost, ttff_s), "
         "runs (every run's times), limits (each with its value and pass) and, with "
         "--reference (or --reference-site NAME, a site of gnss-cli sites), reference (the "
         "accuracy of the positions between runs). --report FILE "
         "writes the report (identity, settings as read back, conditions, tables, CDF plot, "
         "limits, accuracy, every run) as FILE.pdf or FILE.html, with or without a display, and "
         "FILE's base name .csv and .json beside it; --lang and --units choose its language "
         "and lengths.\n"
         "Exit status: 0 done and every --limit met, 1 the receiver cannot be opened or "
         "identified, a limit was not met or the report could not be written, 2 usage error "
         "or a start it lacks, 130 interrupted (the runs so far are printed).\n"},
        {"compare", cmdCompare, "compare SOURCE SOURCE [SOURCE...] [--duration S] [--json]",
         "receivers side by side: position and C/N0 differences", kCompareOptions,
         "SOURCE is a log FILE or a live receiver (--port P, --tcp HOST:PORT, --gpsd G, --sim D; "
         "each repeatable), in the order given: the first is the reference, and every "
         "difference is another receiver minus it. Epochs are matched on their UTC time. Prints "
         "one JSON line per matched epoch (time, fix of each, and per other receiver east, "
         "north, up, horizontal in metres, C/N0 of each satellite and signal both track, "
         "satellites only one has), then the summary in words on standard error; with --json "
         "one object at the end: receivers (name, dialect, epochs, fix shares, and after the "
         "first difference_m, cn0_db, only_in) and matched_epochs. Logs alone are compared "
         "whole; beside a live source they are replayed at their own pace.\n"
         "Exit status: 0 compared, 1 a source cannot be opened or no epoch matched, 2 usage "
         "error (fewer than two sources), 130 interrupted.\n"},
        {"ntrip", cmdNtrip, "ntrip --caster HOST:PORT --mount M|--sourcetable|--nearest [OPTIONS]",
         "NTRIP: a caster's source table, or a mountpoint's RTCM 3", kNtripOptions,
         "NTRIP revision 1 or 2 (chunked transfer decoded before RTCM framing). --sourcetable "
         "prints one JSON object per mountpoint (with its distance when a position is known); "
         "--mount (or --nearest) receives the mountpoint's RTCM 3 and prints one JSON object per "
         "message, as rtcm does, and/or writes the raw bytes to --out. A GGA is sent at the start "
         "and every 10 s to mountpoints that ask for one (with --gga auto, from the receiver's "
         "fix). "
         "With a receiver (--port, --tcp or --sim) the corrections are forwarded to it through its "
         "link, whole frames only and never inside a command, and its epochs are printed as JSON "
         "lines instead. The password is read from the "
         "environment (--password-env), never from the command line, and never printed.\n"
         "Exit status: 0 ended by --duration or Ctrl-C after data, 1 the caster refused (wrong "
         "credentials) or could not be reached, or no RTCM came within --duration, 2 usage "
         "error or a mountpoint the caster does not have.\n",
         0},
        {"serve", cmdServe,
         "serve --port P|--tcp HOST:PORT|--sim D|--replay FILE [--loop] --ntrip [ADDR:]PORT/MOUNT "
         "[--user U --password-env VAR] [--raw [ADDR:]PORT] [--duration S]",
         "serve a source: an NTRIP caster of its RTCM, a raw TCP port", kServeOptions,
         "Serves the source to other programs. --ntrip is an NTRIP caster (revision 1: ICY 200 "
         "OK; revision 2: HTTP/1.1, chunked) whose mountpoint carries the source's whole RTCM 3 "
         "frames with a good CRC (what lies between them, NMEA, is left out), and whose source "
         "table describes it from what is served: message types and rates, systems, the "
         "station's position. With --user the mountpoint needs that user and the password in "
         "the environment variable --password-env names; the source table never does. --raw "
         "passes every byte of the source to every client (what clients send is ignored). Both "
         "listen on 127.0.0.1 unless an address is given; PORT 0 takes a free port, and the "
         "address listened on is said on standard error, as are clients connecting, refused "
         "and leaving. A client that does not read is dropped once 1 MiB waits for it. A "
         "--replay file is played at its own pace (an RTCM file by its epochs, a recording by "
         "its index), from the moment the first client is served.\n"
         "Exit status: 0 ended by --duration or the end of the replay, 1 the source cannot be "
         "opened or a port cannot be listened on (in use), 2 usage error (nothing listens), 130 "
         "interrupted.\n",
         0},
        {"base", cmdBase,
         "base --port P|--tcp HOST:PORT|--sim D [--baud B] status\n"
         "base ... survey --minutes M|--sigma METRES [--by-receiver [--input V]] "
         "[--save-site NAME] [--set [--station N] [--rtcm-port N] [--rtcm-interval S] [--save]]\n"
         "base ... set --ecef X,Y,Z|--llh LAT,LON,HEIGHT [--msl]|--site NAME [--antenna-height H] "
         "[--station N] [--rtcm-port N [--rtcm-baud B]] [--rtcm-interval S] [--save]",
         "set up a receiver as an RTK base: survey in, set, verify, status", kBaseOptions,
         "For a receiver whose dialect can be a base (the NV08C-RTK). Everything typed is checked "
         "before the port is opened.\n"
         "  status  one JSON line: mode and role, position (ECEF and geodetic), station, RTCM "
         "interval, threshold, averaging, the ports known to carry RTCM, the receiver's own fix "
         "and its distance from the position (a warning past the threshold: the receiver sends "
         "no corrections then)\n"
         "  survey  averages the receiver's fixes for --minutes or until --sigma: a JSON line a "
         "second (positions, mean, sigma east/north/up, the mean's accuracy, progress), then the "
         "result; --by-receiver sets the receiver's own averaging and follows its time instead; "
         "--save-site keeps the result as a site, --set makes it the base\n"
         "  set     the base's mode, position, station, RTCM interval and port, each command's "
         "outcome and each setting read back (verified or not), then the status\n"
         "Exit status: 0 done and verified, 1 a command refused or failed, a value that did not "
         "verify, no fix, the source cannot be opened, 2 usage error, a malformed position, an "
         "unknown site, a receiver that cannot be a base, a value out of range (nothing sent), "
         "130 interrupted.\n",
         1},
        {"sites", cmdSites,
         "sites list [--json]\n"
         "sites add NAME --llh LAT,LON[,HEIGHT]|--ecef X,Y,Z [--antenna-height H] [--accuracy M] "
         "[--date D] [--method TEXT] [--note TEXT] [--replace]\n"
         "sites remove NAME\n"
         "sites export FILE.csv|FILE.json\n"
         "sites import FILE.csv|FILE.json [--replace]",
         "the list of named positions the GUI shares: list, add, remove, export, import",
         kSitesOptions,
         "The user's sites (survey marks, base-station points, known antenna positions), kept in "
         "sites.json in the data folder the GUI uses ($GNSS_WORKBENCH_DATA_DIR when set), and "
         "used by summary and ttff --reference-site NAME.\n"
         "  list    a line per site (name, position, antenna height, accuracy, date, method); "
         "--json the list as the export writes it\n"
         "  add     a site NAME (up to 64 characters; names are unique whatever their case): its "
         "mark's position, antenna height (default 0), accuracy, date, method and note\n"
         "  remove  the site NAME (its full name)\n"
         "  export  the list to FILE as CSV (name,lat,lon,height,antenna_height,accuracy,date,"
         "method,note) or JSON, by its extension\n"
         "  import  the sites of FILE into the list; one whose name is taken is kept as it was "
         "and reported, unless --replace\n"
         "Exit status: 0 done, 1 the list or FILE cannot be read or written, a name taken (add, "
         "import: the rest is imported), 2 usage error, a malformed position, NAME or FILE "
         "(nothing written), an unknown site.\n"},
};

// Calls f with each line of a '\n'-separated text.
template <class F> void forEachLine(std::string_view text, F f) {
    while (!text.empty()) {
        const auto nl = text.find('\n');
        f(text.substr(0, nl));
        text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    }
}

// Appends `text` wrapped at 80 columns: its first line goes on after what `out` already holds of
// the current line (`column` wide), the others start `indent` spaces in.
void appendWrapped(std::string &out, std::string_view text, std::size_t column,
                   std::size_t indent) {
    constexpr std::size_t kWidth = 80;
    bool lineStart = true;
    while (!text.empty()) {
        const auto space = text.find(' ');
        const std::string_view word = text.substr(0, space);
        text = space == std::string_view::npos ? std::string_view() : text.substr(space + 1);
        if (word.empty()) continue;
        if (!lineStart && column + 1 + word.size() > kWidth) {
            out += '\n';
            out.append(indent, ' ');
            column = indent;
            lineStart = true;
        }
        if (!lineStart) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        lineStart = false;
    }
    out += '\n';
}

// A help text with "{detection order}" replaced by the rates baud detection tries, in its order
// (core/baud_rates.h), so that the help says what the opener does.
std::string withDetectionOrder(std::string_view text) {
    constexpr std::string_view kMark = "{detection order}";
    std::string out(text);
    if (const auto at = out.find(kMark); at != std::string::npos)
        out.replace(at, kMark.size(), baudList(kDetectionBauds));
    return out;
}

// A details paragraph; "  label   text" keeps its label and is continued under its text.
void appendParagraph(std::string &out, std::string_view paragraph) {
    if (!paragraph.starts_with(' ')) return appendWrapped(out, paragraph, 0, 0);
    const auto labelStart = paragraph.find_first_not_of(' ');
    const auto labelEnd = paragraph.find(' ', labelStart);
    const auto textStart = paragraph.find_first_not_of(' ', labelEnd);
    if (labelEnd == std::string_view::npos || textStart == std::string_view::npos)
        return appendWrapped(out, paragraph, 0, 0);
    out += paragraph.substr(0, textStart);
    appendWrapped(out, paragraph.substr(textStart), textStart, textStart);
}

// "  --name VALUE   help", the help column aligned over the command's options.
void appendOptions(std::string &out, std::span<const OptionSpec> options) {
    const OptionSpec help{"help", "", "this help"};
    const OptionSpec version{"version", "", "the program's version"};
    auto label = [](const OptionSpec &o) {
        std::string l = o.name == "help" ? "-h, --"
                        : o.shortName    ? std::string("-") + o.shortName + ", --"
                                         : std::string("--");
        l += o.name;
        if (!o.value.empty()) l += " " + std::string(o.value);
        return l;
    };
    std::size_t width = label(help).size();
    for (const OptionSpec &o : options) width = std::max(width, label(o).size());
    auto line = [&](const OptionSpec &o) {
        const std::string l = label(o);
        out += "  " + l;
        out.append(width + 2 - l.size(), ' ');
        appendWrapped(out, o.help, 2 + width + 2, 2 + width + 2);
    };
    out += "\noptions:\n";
    for (const OptionSpec &o : options) line(o);
    line(help);
    line(version);
}

} // namespace

std::span<const CommandSpec> commandTable() {
    return kCommands;
}

const CommandSpec *findCommand(std::string_view name) {
    for (const CommandSpec &c : kCommands)
        if (c.name == name) return &c;
    return nullptr;
}

namespace {

// "dialects:" and one line per dialect of the registry: its id and what it is.
void appendDialects(std::string &out, const DialectRegistry &registry) {
    std::size_t width = 0;
    for (const Dialect *d : registry.dialects()) width = std::max(width, d->id.size());
    out += "\ndialects:\n";
    for (const Dialect *d : registry.dialects()) {
        std::string line = "  " + std::string(d->id);
        line.append(width + 4 - d->id.size(), ' ');
        out += line;
        std::string text(d->summary.empty() ? d->displayName : d->summary);
        if (!d->renamablePrefix.empty())
            text += " (renamable prefix " + std::string(d->renamablePrefix) + ")";
        appendWrapped(out, text, line.size(), line.size());
    }
}

// Whether a command's help names dialects (an option or an argument that takes one).
bool takesDialect(const CommandSpec &c) {
    if (c.synopsis.find("DIALECT") != std::string_view::npos) return true;
    for (const OptionSpec &o : c.options)
        if (o.name == "dialect" || o.name == "sim") return true;
    return false;
}

} // namespace

std::string overviewHelp(const DialectRegistry &registry) {
    std::string out = "usage: gnss-cli COMMAND [OPTIONS] [ARGUMENTS]\n"
                      "       gnss-cli help [COMMAND]\n"
                      "       gnss-cli --help | --version | --list-dialects\n"
                      "\nGNSS Workbench without the windows: logs decoded to JSON, live\n"
                      "receivers, settings.\n\ncommands:\n";
    for (const CommandSpec &c : kCommands) {
        forEachLine(c.synopsis, [&](std::string_view form) {
            out += "  ";
            out += form;
            out += '\n';
        });
        out += "      ";
        out += c.summary;
        out += '\n';
    }
    appendDialects(out, registry);
    out += '\n';
    for (std::string_view paragraph :
         {"D and DIALECT are one of the dialects above (D may also be auto, the default: "
          "recognised from the stream).",
          "Every command takes --help and --version; options take their value as --opt VALUE or "
          "--opt=VALUE, and -- ends them. Data goes to standard output (JSON Lines where it is a "
          "stream), messages to standard error.",
          "Exit status: 0 done, 1 failed (input unreadable, receiver refused or silent, no data "
          "within --duration), 2 the request is wrong and nothing was sent (usage, unknown key, "
          "value out of range, malformed sentence, unknown device or mountpoint), 130 "
          "interrupted.",
          "--list-dialects prints one line per dialect for scripts and shell completion: its id, "
          "'sim' when --sim plays it (else '-'), and its name, separated by tabs.",
          "See gnss-cli help COMMAND, gnss-cli(1) and docs/cli.md."})
        appendWrapped(out, paragraph, 0, 0);
    return out;
}

std::string commandHelp(const CommandSpec &command, const DialectRegistry &registry) {
    std::string out;
    bool first = true;
    forEachLine(command.synopsis, [&](std::string_view form) {
        out += first ? "usage: gnss-cli " : "       gnss-cli ";
        out += form;
        out += '\n';
        first = false;
    });
    out += '\n';
    forEachLine(withDetectionOrder(command.details),
                [&](std::string_view paragraph) { appendParagraph(out, paragraph); });
    appendOptions(out, command.options);
    if (takesDialect(command)) appendDialects(out, registry);
    return out;
}

} // namespace gnss::cli
