#!/usr/bin/env bash
# Installs, builds (warnings as errors) and runs every test through CTest, three times over:
#   1. build/       Release, g++: the whole suite
#      build-web/   the web page (scripts/web.sh), checked in headless Chromium (tests/web)
#   2. build-asan/  the whole suite again under AddressSanitizer + UBSan (any report fails)
#   3. build-fuzz/  each libFuzzer target for CONVEXLOC_FUZZ_SECONDS (default 20) from its seeds
# Fails when any test fails. Usage: scripts/test.sh [--quick]   (--quick: step 1 only)
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
jobs=$(nproc)
ctest_args=(--output-on-failure --parallel "$jobs" --timeout 1500)
# each ctest run's results (per-test times), for the slowest tests at the end
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

# when a step fails, say which one
step="set-up"
step_start=$SECONDS
step_times=()
trap 'echo "convexloc: FAILED in step: $step" >&2; summary' ERR
span() { printf '%dm%02ds' $(($1 / 60)) $(($1 % 60)); }
elapsed() { span $((SECONDS - start)); }
# the step now starting; the one before it is timed
begin() {
  local took=$((SECONDS - step_start))
  step_times+=("$(printf '  %-16s %s' "$step" "$(span "$took")")")
  echo "convexloc: $step took $(span "$took"); now: $1 [$(elapsed)]"
  step=$1
  step_start=$SECONDS
}
# each step's time and the ten slowest tests of the runs so far (from their JUnit reports)
summary() {
  begin "summary"
  echo "convexloc: time per step"
  printf '%s\n' "${step_times[@]}"
  local run
  for run in plain sanitized fuzz; do
    compgen -G "$results/$run-*.xml" >/dev/null || continue
    echo "convexloc: the ten slowest tests of the $run run (seconds)"
    /usr/bin/python3 - "$results"/"$run"-*.xml <<'PY'
import sys
import xml.etree.ElementTree as ET

cases = [(float(c.get("time", 0)), c.get("name", "?"))
         for path in sys.argv[1:] for c in ET.parse(path).getroot().iter("testcase")]
for seconds, name in sorted(cases, reverse=True)[:10]:
    print(f"  {seconds:8.1f}  {name}")
PY
  done
}

begin "plain build"
scripts/setup.sh --werror --tests
begin "plain tests"
echo "convexloc: running the test suite (build/) [$(elapsed)]"
ctest --test-dir build "${ctest_args[@]}" --output-junit "$results/plain-all.xml"
begin "web page"
echo "convexloc: building the web page and testing it in Chromium (build-web/) [$(elapsed)]"
scripts/web.sh
/usr/bin/python3 tests/web/web_page_test.py build-web/site
if [[ "${1:-}" == "--quick" ]]; then
  summary
  exit 0
fi

begin "sanitized build"
scripts/setup.sh --werror --tests --sanitize
begin "sanitized tests"
echo "convexloc: running the test suite under ASan + UBSan (build-asan/) [$(elapsed)]"
# Any report aborts the process, which fails its test; leaks are reports too.
# The install test is left out: it builds a consumer without the sanitizer runtime.
# The hostile tests generate smaller huge inputs here (the plain run has the full sizes).
asan=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export CONVEXLOC_HOSTILE_SCALE=${CONVEXLOC_HOSTILE_SCALE_ASAN:-0.1}
# The tests that run the real viewer turn leak detection off themselves (tests/viewer: Mesa's
# driver leaks what LeakSanitizer can no longer attribute at exit).
ASAN_OPTIONS=$asan ctest --test-dir build-asan "${ctest_args[@]}" --label-exclude install \
  --output-junit "$results/sanitized-all.xml"
unset UBSAN_OPTIONS CONVEXLOC_HOSTILE_SCALE

begin "fuzz build"
scripts/setup.sh --werror --tests --fuzz
begin "fuzz runs"
echo "convexloc: fuzzing each target for ${CONVEXLOC_FUZZ_SECONDS:-20} s (build-fuzz/) [$(elapsed)]"
cmake -S . -B build-fuzz -DCONVEXLOC_FUZZ_SECONDS="${CONVEXLOC_FUZZ_SECONDS:-20}" >/dev/null
ctest --test-dir build-fuzz "${ctest_args[@]}" --label-regex fuzz --output-junit "$results/fuzz-all.xml"
summary
echo "convexloc: all tests passed: plain, sanitized and fuzzed [$(elapsed)]"
