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

# when a step fails, say which one
step="set-up"
trap 'echo "convexloc: FAILED in step: $step" >&2' ERR
elapsed() { printf '%dm%02ds' $(((SECONDS - start) / 60)) $(((SECONDS - start) % 60)); }

step="plain build"
scripts/setup.sh --werror
step="plain tests"
echo "convexloc: running the test suite (build/) [$(elapsed)]"
ctest --test-dir build "${ctest_args[@]}"
step="web page"
echo "convexloc: building the web page and testing it in Chromium (build-web/) [$(elapsed)]"
scripts/web.sh
/usr/bin/python3 tests/web/web_page_test.py build-web/site
if [[ "${1:-}" == "--quick" ]]; then exit 0; fi

step="sanitized build"
scripts/setup.sh --werror --sanitize
step="sanitized tests"
echo "convexloc: running the test suite under ASan + UBSan (build-asan/) [$(elapsed)]"
# Any report aborts the process, which fails its test; leaks are reports too.
# The install test is left out: it builds a consumer without the sanitizer runtime.
# The hostile tests generate smaller huge inputs here (the plain run has the full sizes).
asan=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export CONVEXLOC_HOSTILE_SCALE=${CONVEXLOC_HOSTILE_SCALE_ASAN:-0.1}
ASAN_OPTIONS=$asan ctest --test-dir build-asan "${ctest_args[@]}" --label-exclude install \
  --exclude-regex '^viewer[.]smoke[.]'
# The viewer's smoke tests run the real app on Mesa (llvmpipe) under Xvfb. Mesa's driver,
# which the GL library loads and unloads, leaks a few hundred bytes that LeakSanitizer can
# no longer attribute at exit (its module is gone): these tests run with leak detection
# off and every other check on.
ASAN_OPTIONS=${asan/detect_leaks=1/detect_leaks=0} ctest --test-dir build-asan "${ctest_args[@]}" \
  --tests-regex '^viewer[.]smoke[.]' --no-tests=ignore
unset UBSAN_OPTIONS CONVEXLOC_HOSTILE_SCALE

step="fuzz build"
scripts/setup.sh --werror --fuzz
step="fuzz runs"
echo "convexloc: fuzzing each target for ${CONVEXLOC_FUZZ_SECONDS:-20} s (build-fuzz/) [$(elapsed)]"
cmake -S . -B build-fuzz -DCONVEXLOC_FUZZ_SECONDS="${CONVEXLOC_FUZZ_SECONDS:-20}" >/dev/null
ctest --test-dir build-fuzz "${ctest_args[@]}" --label-regex fuzz
echo "convexloc: all tests passed: plain, sanitized and fuzzed [$(elapsed)]"
