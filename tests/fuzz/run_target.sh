#!/usr/bin/env bash
# Fuzzes one libFuzzer binary for a bounded time from its seeds, and prints its figures.
# Usage: run_target.sh BINARY SECONDS WORKDIR SEEDDIR...
#   WORKDIR is emptied and receives the inputs the run discovers (never the committed seeds)
#   and any crash, as WORKDIR/crash-<sha1>. Exit status: 0 when nothing was found.
# FUZZ_SEED (environment): libFuzzer's random seed; unset or 0 draws a fresh one. The CTest
#   runs fix it, so that a test run explores the same inputs each time and a failure in it
#   reproduces; campaigns (run.sh) draw a fresh seed to explore further.
set -euo pipefail
bin=$1 seconds=$2 work=$3
shift 3
seeds=()
for d in "$@"; do [[ -d $d ]] && seeds+=("$d"); done
rm -rf "$work"
mkdir -p "$work/corpus"
log=$work/log.txt
status=0
seed=()
[[ ${FUZZ_SEED:-0} != 0 ]] && seed=(-seed="$FUZZ_SEED")
# -timeout: an input taking 10 s is a hang; -rss_limit_mb: a leak or a blow-up is a finding
"$bin" -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 "${seed[@]}" -artifact_prefix="$work/" "$work/corpus" "${seeds[@]}" >"$log" 2>&1 ||
  status=$?
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
name=$(basename "$bin")
echo "$name: ${runs:-?} executions in ${seconds} s, ${rate:-?} per second, corpus $(ls "$work/corpus" | wc -l) new inputs"
if ((status != 0)); then
  tail -n 60 "$log"
  echo "$name: FAILED (status $status); the input is in $work/, make it a regression test in tests/data/fuzz/"
fi
exit "$status"
