#!/usr/bin/env bash
# Installs, builds (warnings as errors) and runs every test through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --werror
echo "convexloc: running the test suite"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 1500
