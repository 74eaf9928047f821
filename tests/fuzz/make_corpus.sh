#!/usr/bin/env bash
# Regenerates the seed corpus of tests/fuzz/corpus/<harness>/ from a normal build, with the
# project's own code only:
#   - gnss_fuzz_seeds: RTCM frames from protocol/rtcm's encoder, every setting of every schema,
#     a settings profile per dialect, NTRIP 1 and 2 caster replies, recordings written by the
#     recorder (and torn, cut, holed, foreign indexes);
#   - gnss-sim --stdout: a few seconds of each simulated receiver (answering its probe and
#     settings queries), clean and with line faults, cut at line ends into pieces under 1 KB
#     (run.sh fuzzes the NMEA streams with -max_len=1024), and under 4 KB for the log index;
#   - gnss-cli record --sim: two seconds of two simulated receivers as recordings;
#   - the sentences typed in the tests (tests/**/*.cpp), one file per vendor.
# The seeds are the files named seed_*: this script replaces those and leaves the others alone —
# inputs fuzzing found (tests/fuzz/run.sh --merge: hash names) and the inputs of past findings
# kept as regressions (regression_*).
#
#   tests/fuzz/make_corpus.sh [BUILD_DIR]      (default build/dev; needs gnss-sim, gnss-cli and
#                                               gnss_fuzz_seeds: cmake --build BUILD_DIR
#                                               --target gnss-sim gnss-cli gnss_fuzz_seeds)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build/dev}
sim=$build/app/sim/gnss-sim
cli=$build/app/cli/gnss-cli
seeds=$build/tests/fuzz/gnss_fuzz_seeds
for tool in "$sim" "$cli" "$seeds"; do
  [ -x "$tool" ] || { echo "missing $tool (build it first)" >&2; exit 1; }
done

corpus=tests/fuzz/corpus
stream_harnesses=(fuzz_stream_decoder fuzz_epochs_state fuzz_log_scan)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

mkdir -p "$corpus"
find "$corpus" -type f -name 'seed_*' -delete
"$seeds" "$corpus"
for h in "${stream_harnesses[@]}" fuzz_log_index fuzz_recording_index; do mkdir -p "$corpus/$h"; done

# Control bytes (fuzz_nmea.h): byte 0 = dialect (0 auto, 1 nvs, 2 geostar, 3 nemerix, 4 nmea)
# + 8 when lenient; byte 1 = a chunking for the decoder harnesses (0x23: chunks of 1-8 bytes),
# 2 threads with 32-byte least segments for fuzz_log_scan (0x15).
write_stream() { # NAME DIALECT_BYTE FILE
  local name=$1 b0=$2 file=$3
  for h in "${stream_harnesses[@]}"; do
    local b1='\x23'
    [ "$h" = fuzz_log_scan ] && b1='\x15'
    { printf "\\x$b0$b1"; cat "$file"; } > "$corpus/$h/seed_$name"
  done
}

# Simulator output: the probe and readable settings queried at start, 3 s of output at 2x.
declare -A dialect_byte=([nvs]=01 [geostar]=02 [nemerix]=03 [nmea]=04)
declare -A queries=(
  [nvs]='rtk.MODE rtk.PVTRATE pps.type idl.stations'
  [geostar]='output.RATE output.NMEAV'
  [nemerix]='rate.GGA'
  [nmea]=''
)
for d in nvs geostar nemerix nmea; do
  commands=()
  [ -n "${queries[$d]}" ] && mapfile -t commands < <("$cli" encode "$d" --query ${queries[$d]})
  for variant in clean faults; do
    args=(--dialect "$d" --stdout --speed 2 --seed 7)
    [ "$variant" = faults ] && args+=(--faults badcs=0.05,truncate=0.05,binary=0.1)
    { sleep 0.3; for c in "${commands[@]}"; do printf '%s\r\n' "$c"; done; sleep 3; } |
      "$sim" "${args[@]}" > "$tmp/$d-$variant.log"
    split -C 1000 -d -a 2 "$tmp/$d-$variant.log" "$tmp/$d-$variant."
    for piece in "$tmp/$d-$variant".[0-9][0-9]; do
      n=${piece##*.}
      b0=${dialect_byte[$d]}
      [ "$variant" = faults ] && b0=08     # auto detection, lenient
      [ "$n" = 00 ] && [ "$variant" = clean ] && b0=00 # auto detection from the start
      # + 0x20: the piece repeated into a stream longer than a line may be (fuzz_nmea.h)
      [ "$n" = 01 ] && [ "$variant" = clean ] && b0=$(printf '%02x' $((0x$b0 | 0x20)))
      write_stream "sim_${d}_${variant}_$n" "$b0" "$piece"
    done
    # The log index (fuzz_log_index.cpp): byte 0 as above, byte 1 the layout (0x0d: 2 threads,
    # 128-byte pieces), byte 2 N and the modes (clean 0x37: N = 8, grown and opened in a
    # LogView; faults 0x13: N = 4, grown), byte 3 a seed; the first two pieces under 4 KB.
    split -C 4000 -d -a 2 "$tmp/$d-$variant.log" "$tmp/$d-$variant.index."
    for n in 00 01; do
      piece=$tmp/$d-$variant.index.$n
      [ -f "$piece" ] || continue
      b0=${dialect_byte[$d]} b2=37
      [ "$variant" = faults ] && b0=08 b2=13
      { printf "\\x$b0\\x0d\\x$b2\\x07"; cat "$piece"; } > "$corpus/fuzz_log_index/seed_sim_${d}_${variant}_$n"
    done
  done
done

# Recordings by the project's recorder (fuzz_recording_index.cpp): byte 0 = 4 (both files, the
# log viewer opens it too), bytes 1-2 the index's length (little endian), the index, the data.
for d in nvs geostar; do
  "$cli" record --sim "$d" --out "$tmp/rec-$d.nmea" --duration 2 > /dev/null 2>&1
  n=$(stat -c %s "$tmp/rec-$d.nmea.idx")
  { printf "$(printf '\\x04\\x%02x\\x%02x' $((n & 255)) $((n >> 8)))"
    cat "$tmp/rec-$d.nmea.idx" "$tmp/rec-$d.nmea"; } > "$corpus/fuzz_recording_index/seed_record_$d"
done

# Sentences typed in the tests (spec examples, test rows): one file per vendor, CR LF ended.
grep -rhoE '\$[A-Z][A-Z0-9]{3,}[^"\\]*\*[0-9A-Fa-f]{2}' tests --include='*.cpp' | sort -u \
  > "$tmp/typed.txt"
typed() { # NAME DIALECT_BYTE REGEX
  grep -E "$3" "$tmp/typed.txt" | sed 's/$/\r/' > "$tmp/typed-$1.txt" || true
  [ -s "$tmp/typed-$1.txt" ] || return 0
  split -C 1000 -d -a 2 "$tmp/typed-$1.txt" "$tmp/typed-$1."
  for piece in "$tmp/typed-$1".[0-9][0-9]; do
    write_stream "typed_$1_${piece##*.}" "$2" "$piece"
  done
}
typed nvs 01 '^\$(PNVG|GPGPQ)'
typed geostar 02 '^\$GPSGG'
typed nemerix 03 '^\$PNMRX'
typed nmea 00 '^\$(G[PLANBQ]|BD|CC|GI)[A-Z]{3},'

du -sh "$corpus"
for h in "$corpus"/*; do printf '%6d files  %s\n' "$(ls "$h" | wc -l)" "${h##*/}"; done
