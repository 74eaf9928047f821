#!/usr/bin/env bash
# Runs the libFuzzer harnesses of the `fuzz` preset, one after the other, each for SECONDS, with
# one worker at nice 19 (the machine is shared with builders). Prints, per harness, the
# executions, executions per second, coverage (libFuzzer's cov: edges, ft: features) and corpus
# size; crashes are kept under build/fuzz/artifacts/ and make the script fail.
#
#   tests/fuzz/run.sh [--fast] [--merge] [--runs N] SECONDS [HARNESS...]   (default: every one)
#
# --fast runs the fuzz-fast preset's binaries instead: the same harnesses with UBSan but without
# AddressSanitizer, several times the executions per second (an out-of-bounds read that does not
# crash goes unseen there: the ASan campaign covers that, the fast one covers more inputs).
#
# --runs N stops a harness after N executions, or after SECONDS if that comes first (0: no time
# limit), so that a campaign can give each harness the same number of executions.
#
# New inputs go to a scratch folder, never straight into the committed corpus. With --merge,
# those that reach new coverage are then merged into tests/fuzz/corpus/<harness>/ (libFuzzer
# -merge=1); review and commit them like code.
#
# Builds the fuzz preset first when its binaries are missing (clang and libfuzzer-14-dev:
# ./quickstart.sh installs them for this).
set -euo pipefail
cd "$(dirname "$0")/../.."

merge=0
preset=fuzz
runs=-1
while [ $# -gt 0 ]; do
  case $1 in
    --merge) merge=1 ;;
    --fast) preset=fuzz-fast ;;
    --runs) runs=${2:?--runs takes a number of executions}; shift ;;
    *) break ;;
  esac
  shift
done
seconds=${1:?usage: tests/fuzz/run.sh [--fast] [--merge] [--runs N] SECONDS [HARNESS...]}
shift
harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=(fuzz_stream_decoder fuzz_epochs_state
  fuzz_settings_roundtrip fuzz_profile_import fuzz_rtcm fuzz_log_scan fuzz_log_index
  fuzz_ntrip_response fuzz_recording_index fuzz_caster_request fuzz_mixed_stream)

build=build/$preset
missing=0
for h in "${harnesses[@]}"; do [ -x "$build/tests/fuzz/$h" ] || missing=1; done
if [ $missing -eq 1 ]; then
  cmake --preset "$preset" >/dev/null
  nice -n 10 cmake --build --preset "$preset" --parallel 1 --target "${harnesses[@]}"
fi

artifacts=$build/artifacts
mkdir -p "$artifacts"
failed=0
printf '%-24s %12s %9s %7s %7s %14s %s\n' harness executions exec/s cov ft corpus result
for h in "${harnesses[@]}"; do
  corpus=tests/fuzz/corpus/$h
  # GNSS_FUZZ_WORK=DIR keeps each harness's new inputs in DIR/<harness> from one run to the next
  # (a campaign of many runs goes on from the coverage it reached); by default they are dropped.
  if [ -n "${GNSS_FUZZ_WORK:-}" ]; then
    scratch=$GNSS_FUZZ_WORK/$h
    mkdir -p "$scratch"
  else
    scratch=$(mktemp -d)
  fi
  # GNSS_FUZZ_LOG_TAG=T names the log <harness>.T.log, for runs of one harness side by side.
  log=$build/$h${GNSS_FUZZ_LOG_TAG:+.$GNSS_FUZZ_LOG_TAG}.log
  dict=()
  [ -f "tests/fuzz/$h.dict" ] && dict=(-dict="tests/fuzz/$h.dict")
  # Longest input: 1 KB for the NMEA streams (a control bit repeats the payload into a stream
  # longer than a line may be, so long lines and logs are still reached), one whole RTCM frame
  # and more for RTCM and for NMEA with RTCM, a profile file for profiles; 4 KB for caster
  # replies (a control bit repeats them past the longest head) and recordings, past the caster's
  # longest head (8 KB) for client requests, 8 KB for the log index (logs of a few dozen
  # epochs; the harness cuts anything over 64 KB).
  case $h in
    fuzz_rtcm | fuzz_mixed_stream) max_len=2100 ;;
    fuzz_profile_import | fuzz_settings_roundtrip | fuzz_ntrip_response) max_len=4096 ;;
    fuzz_caster_request) max_len=8400 ;;
    fuzz_recording_index) max_len=4096 ;;
    fuzz_log_index) max_len=8192 ;;
    *) max_len=1024 ;;
  esac
  set +e
  # -timeout 10: one input that takes seconds is a finding (a hang) too. ASan: no fill of new
  # blocks and a smaller quarantine (a quarter faster; use-after-free is still caught).
  ASAN_OPTIONS=${ASAN_OPTIONS:-max_malloc_fill_size=0:quarantine_size_mb=16} \
    nice -n 19 "$build/tests/fuzz/$h" "$scratch" "$corpus" "${dict[@]}" \
    -max_total_time="$seconds" -runs="$runs" -max_len=$max_len -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$h-" >"$log" 2>&1
  status=$?
  set -e
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+.*cov: ' "$log" | tail -1)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9]*[a-zA-Z]*\).*/\1/p' <<<"$last")
  result=ok
  if [ $status -ne 0 ]; then
    result="FAILED (exit $status; see $log and $artifacts/)"
    failed=1
  fi
  if [ $merge -eq 1 ] && [ $status -eq 0 ]; then
    nice -n 19 "$build/tests/fuzz/$h" -merge=1 -max_len=$max_len "$corpus" "$scratch" \
      >"$build/$h.merge.log" 2>&1
  fi
  [ -n "${GNSS_FUZZ_WORK:-}" ] || rm -rf "$scratch"
  printf '%-24s %12s %9s %7s %7s %14s %s\n' "$h" "${execs:-?}" "${speed:-?}" "${cov:-?}" \
    "${ft:-?}" "${corp:-?}" "$result"
done
exit $failed
