#!/usr/bin/env bash
# A fuzz campaign that goes on until every harness has run TARGET executions, across as many
# sessions as it takes: the executions each harness has had and the inputs it found are kept in
# WORKDIR, so running it again resumes where it stopped.
#
#   tests/fuzz/campaign.sh [--fast] [--target N] [--slice SECONDS] [--workers W]
#                          [--until HH:MM] WORKDIR [HARNESS...]
#   tests/fuzz/campaign.sh --report WORKDIR
#
# Each worker (default 1) takes the harness furthest from the target that no other worker runs
# (or, when every harness left is running, shares the furthest of those: the last long harness
# gets every core), gives it a slice (default 600 s, or the executions it still lacks if fewer;
# workers sharing one may pass its target by a slice), adds what it ran to WORKDIR/ledger.tsv
# and takes the next. It stops when every harness has its TARGET (default
# 10 000 000), at --until (the local time after which no slice starts; a slice never runs past
# it), or on a finding: a crash or a broken invariant stops that harness (its input under
# build/<preset>/artifacts/, its row marked) and the campaign exits 1 at the end.
# Slices run through tests/fuzz/run.sh (nice 19, the corpus in WORKDIR/corpus/<harness>).
set -euo pipefail
cd "$(dirname "$0")/../.."

fast=()
preset=fuzz
target=10000000
slice=600
workers=1
until=""
report=0
while [ $# -gt 0 ]; do
  case $1 in
    --fast) fast=(--fast); preset=fuzz-fast ;;
    --target) target=${2:?--target takes a number of executions}; shift ;;
    --slice) slice=${2:?--slice takes seconds}; shift ;;
    --workers) workers=${2:?--workers takes a number}; shift ;;
    --until) until=${2:?--until takes HH:MM}; shift ;;
    --report) report=1 ;;
    -*) echo "campaign.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
  shift
done
work=${1:?usage: tests/fuzz/campaign.sh [--fast] [--target N] [--slice S] [--workers W] [--until HH:MM] WORKDIR [HARNESS...]}
shift
mkdir -p "$work/corpus" "$work/busy"
ledger=$work/ledger.tsv
[ -f "$ledger" ] || printf 'harness\texecutions\tslices\tseconds\tresult\n' >"$ledger"

print_ledger() {
  printf '%-24s %14s %7s %9s %10s  %s\n' harness executions slices seconds exec/s result
  tail -n +2 "$ledger" | sort | while IFS=$'\t' read -r h e n s r; do
    printf '%-24s %14s %7s %9s %10s  %s\n' "$h" "$e" "$n" "$s" "$([ "$s" -gt 0 ] && echo $((e / s)) || echo -)" "$r"
  done
}
if [ $report -eq 1 ]; then
  print_ledger
  exit 0
fi

harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=(fuzz_stream_decoder fuzz_epochs_state
  fuzz_settings_roundtrip fuzz_profile_import fuzz_rtcm fuzz_log_scan fuzz_log_index
  fuzz_ntrip_response fuzz_recording_index fuzz_caster_request fuzz_mixed_stream)
for h in "${harnesses[@]}"; do
  grep -q "^$h	" "$ledger" || printf '%s\t0\t0\t0\tok\n' "$h" >>"$ledger"
done

# Built once before the workers start (run.sh would otherwise build in each of them).
missing=0
for h in "${harnesses[@]}"; do [ -x "build/$preset/tests/fuzz/$h" ] || missing=1; done
if [ $missing -eq 1 ]; then
  cmake --preset "$preset" >/dev/null
  nice -n 10 cmake --build --preset "$preset" --parallel "$workers" --target "${harnesses[@]}"
fi

# Busy files of campaigns that are gone (killed, or of the one-file-per-harness format before).
for f in "$work"/busy/*; do
  [ -f "$f" ] || continue
  owner=$(cat "$f" 2>/dev/null || true)
  [ -n "$owner" ] && kill -0 "$owner" 2>/dev/null || rm -f "$f"
done

deadline=0
[ -n "$until" ] && deadline=$(date -d "$until" +%s)
[ -n "$until" ] && [ "$deadline" -le "$(date +%s)" ] && deadline=$((deadline + 86400))

# Under the ledger's lock: the harness furthest from the target, not failed, that no worker
# runs; when every harness left is running (fewer harnesses than workers), the furthest of those,
# shared: two libFuzzer processes on one corpus folder each add what they find to it, and the
# core would otherwise stand idle. A worker is running a harness while its busy file
# (busy/<harness>.<campaign>-<worker>: campaigns run side by side on one folder do not share
# names) names a live campaign; one that was killed leaves a file naming a process that is gone,
# removed here.
pick() {
  local best="" least=-1 shared="" sleast=-1 h e n s r f owner busy
  while IFS=$'\t' read -r h e n s r; do
    [[ " ${harnesses[*]} " == *" $h "* ]] || continue
    [ "$r" = ok ] && [ "$e" -lt "$target" ] || continue
    busy=0
    for f in "$work/busy/$h".*; do
      [ -f "$f" ] || continue
      owner=$(cat "$f" 2>/dev/null || true)
      if [ -n "$owner" ] && kill -0 "$owner" 2>/dev/null; then busy=1; else rm -f "$f"; fi
    done
    if [ $busy -eq 1 ]; then
      if [ $sleast -lt 0 ] || [ "$e" -lt $sleast ]; then shared=$h sleast=$e; fi
    elif [ $least -lt 0 ] || [ "$e" -lt $least ]; then
      best=$h least=$e
    fi
  done < <(tail -n +2 "$ledger")
  [ -n "$best" ] || best=$shared
  [ -n "$best" ] && echo "$campaign" >"$work/busy/$best.$campaign-$slot"
  echo "$best"
}

# Under the lock: adds a slice's executions and seconds to the harness's row.
record() {
  local h=$1 add=$2 secs=$3 result=$4 me=$5
  awk -F'\t' -v OFS='\t' -v h="$h" -v a="$add" -v s="$secs" -v r="$result" \
    'NR > 1 && $1 == h { $2 += a; $3 += 1; $4 += s; if (r != "ok") $5 = r } { print }' \
    "$ledger" >"$ledger.new"
  mv "$ledger.new" "$ledger"
  rm -f "$work/busy/$h.$me"
}

worker() {
  local slot=$1 h done_ secs start left status row execs
  while :; do
    if [ $deadline -gt 0 ]; then
      left=$((deadline - $(date +%s)))
      [ $left -ge 30 ] || return 0
      secs=$((left < slice ? left : slice))
    else
      secs=$slice
    fi
    h=$(flock "$ledger.lock" bash -c "$(declare -f pick); harnesses=(${harnesses[*]}); \
      target=$target; work='$work'; ledger='$ledger'; campaign=$$; slot=$slot; pick")
    [ -n "$h" ] || return 0
    done_=$(awk -F'\t' -v h="$h" '$1 == h { print $2 }' "$ledger")
    start=$(date +%s)
    set +e
    row=$(GNSS_FUZZ_WORK="$work/corpus" GNSS_FUZZ_LOG_TAG="$$-$slot" tests/fuzz/run.sh "${fast[@]}" \
      --runs $((target - done_)) "$secs" "$h" | tail -1)
    status=$?
    set -e
    execs=$(awk '{ print $2 }' <<<"$row")
    [[ $execs =~ ^[0-9]+$ ]] || execs=0
    local result=ok
    [ $status -eq 0 ] || result="finding ($(date +%F) slice: see build/$preset/$h.$$-$slot.log)"
    flock "$ledger.lock" bash -c "$(declare -f record); ledger='$ledger'; work='$work'; \
      record '$h' $execs $(($(date +%s) - start)) '$result' $$-$slot"
    echo "$(date +%T) $row"
  done
}

pids=()
for ((w = 0; w < workers; ++w)); do
  worker "$w" &
  pids+=($!)
  sleep 2 # the first pick is made before the next worker picks
done
for p in "${pids[@]}"; do wait "$p"; done
print_ledger
! grep -q $'\tfinding' "$ledger"
