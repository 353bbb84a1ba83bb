#!/usr/bin/env bash
# A fuzzing campaign: builds build-fuzz/ (clang-14, libFuzzer + ASan + UBSan) and fuzzes each
# target in turn for SECONDS from its seeds, then prints executions per second and in total.
# Usage: tests/fuzz/run.sh [SECONDS [TARGET...]]      e.g. tests/fuzz/run.sh 600
# Targets: the fuzz_* binaries of build-fuzz/tests/fuzz. What a run discovers stays in
# build-fuzz/campaign/<target>/corpus (copy the interesting part to tests/fuzz/corpus/);
# a crash stops that target, its input is build-fuzz/campaign/<target>/crash-*: add it to
# tests/data/fuzz/<target>/ and fix the bug; the replay tests then keep it fixed.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-600}
shift || true
scripts/setup.sh --fuzz >/dev/null
targets=("$@")
if ((${#targets[@]} == 0)); then
  for bin in build-fuzz/tests/fuzz/fuzz_*; do targets+=("${bin##*/fuzz_}"); done
fi
failed=0
summary=()
for t in "${targets[@]}"; do
  echo "== fuzz_$t for $seconds s"
  if line=$(tests/fuzz/run_target.sh "build-fuzz/tests/fuzz/fuzz_$t" "$seconds" \
              "build-fuzz/campaign/$t" "tests/fuzz/corpus/$t" "tests/data/fuzz/$t"); then
    summary+=("$line")
  else
    summary+=("$(head -n 1 <<<"$line") -- FOUND A CRASH")
    echo "$line"
    failed=1
  fi
  echo "${summary[-1]}"
done
echo
echo "== summary ($seconds s per target)"
printf '%s\n' "${summary[@]}"
exit "$failed"
