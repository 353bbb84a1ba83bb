#!/usr/bin/env bash
# Installs what convexloc needs from Debian's packages (only what is missing), then
# configures and builds one build folder.
# Usage: scripts/setup.sh [--werror] [--tests] [--sanitize | --fuzz | --bench | --python]
#   (default)   build/       Release, g++: the tools, the viewer, the tests
#   --tests     also installs what only the tests use (scripts/test.sh passes it): the web
#               page's tool chain and browser, the fuzzing compiler, xdotool, rsvg-convert,
#               mypy and the Python packaging and geo tools; the main job needs none of them
#   --sanitize  build-asan/  g++ with AddressSanitizer + UBSan (core -O1, the rest -Og):
#                            everything but the bench
#   --fuzz      build-fuzz/  clang-14 -O1 with libFuzzer + ASan + UBSan: the core and the
#                            fuzz targets of tests/fuzz only (warnings are not errors here:
#                            the g++ builds hold that line, clang's warnings differ)
#   --bench     build-bench/ Release, g++: convexloc-bench with GEOS and CGAL beside it
#                            (also installs libgeos-dev, libcgal-dev, gnuplot-nox, and
#                            python3-shapely, python3-scipy for tests/bench/python_peers.py)
#   --python    only what the Python package needs to build (a compiler, CMake, pybind11,
#               numpy, Boost's headers, venv and pip), then nothing else: install it with
#               `python3 -m venv --system-site-packages .venv && .venv/bin/pip install
#               --no-build-isolation .` (docs/python.md)
# With --tests every other variant installs emscripten, dpkg-dev, fonts-dejavu-core (scripts/web.sh
# builds the web page with them) and chromium, python3-websocket (tests/web drives the page).
# Every variant installs pybind11-dev, python3-numpy and python3-pytest (and, for the Python
# module's Dask path, its pictures, geo interop, packaging and type checks, python3-dask,
# python3-distributed, python3-pandas, python3-matplotlib, python3-shapely, python3-geopandas,
# python3-venv, python3-setuptools, python3-wheel, python3-pip, python3-build and
# python3-mypy): the plain and bench
# builds make the Python module (build*/python; the sanitized and fuzz builds leave it out).
set -euo pipefail
cd "$(dirname "$0")/.."

werror=OFF
variant=plain
tests=no
for arg in "$@"; do
  case $arg in
    --werror) werror=ON ;;
    --tests) tests=yes ;;
    --sanitize) variant=sanitize ;;
    --fuzz) variant=fuzz ;;
    --bench) variant=bench ;;
    --python) variant=python ;;
    *) echo "usage: scripts/setup.sh [--werror] [--tests] [--sanitize | --fuzz | --bench | --python]" >&2; exit 2 ;;
  esac
done

# the main job: the CLI, the viewer (Xvfb where there is no display), the Python module
packages=(cmake ninja-build g++ pkg-config libgmp-dev libboost-dev libcli11-dev
          libgtest-dev libbenchmark-dev libglfw3-dev libglm-dev libimgui-dev libstb-dev python3-glad
          xvfb xauth libgl1-mesa-dri
          python3-dev pybind11-dev python3-numpy python3-pytest
          python3-dask python3-distributed python3-pandas)
if [[ $tests == yes ]]; then
  packages+=(xdotool librsvg2-bin clang-14 libclang-rt-14-dev python3-mypy
             python3-shapely python3-matplotlib python3-geopandas
             python3-venv python3-setuptools python3-wheel python3-pip python3-build
             emscripten dpkg-dev fonts-dejavu-core chromium python3-websocket)
fi
if [[ $variant == fuzz ]]; then
  packages+=(clang-14 libclang-rt-14-dev)
fi
if [[ $variant == bench ]]; then
  packages+=(libgeos-dev libcgal-dev gnuplot-nox python3-shapely python3-scipy)
fi
# the Python package alone (GMP is optional: without it core's exact numbers are Boost's)
if [[ $variant == python ]]; then
  packages=(g++ make cmake python3-dev pybind11-dev python3-numpy libboost-dev
            python3-venv python3-setuptools python3-wheel python3-pip)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "convexloc: installing Debian packages: ${missing[*]}"
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "convexloc: all Debian packages present"
fi

if [[ $variant == python ]]; then
  echo "convexloc: ready for: python3 -m venv --system-site-packages .venv &&" \
       ".venv/bin/pip install --no-build-isolation ."
  exit 0
fi

if [[ -n "${CI:-}" ]]; then werror=ON; fi

# the fuzz build: -O1 keeps sanitized code fast enough to fuzz and its reports readable; -g1
# gives lines
fuzz_flags=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" "-DCMAKE_C_FLAGS_DEBUG=-O1 -g1")
# the sanitized build: core, where the tests spend their time, at -O1; the tests, the tools and
# the viewer at -Og, which g++ compiles in 60% of the time with ASan and UBSan and which runs
# them as fast (their time is core's)
asan_flags=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-Og -g1" "-DCMAKE_C_FLAGS_DEBUG=-Og -g1"
            -DCONVEXLOC_CORE_FLAGS=-O1)
case $variant in
  plain)
    dir=build
    what="Release"
    options=(-DCMAKE_BUILD_TYPE=Release) ;;
  sanitize)
    dir=build-asan
    what="AddressSanitizer + UndefinedBehaviorSanitizer"
    options=("${asan_flags[@]}" -DCONVEXLOC_SANITIZE=ON -DCONVEXLOC_BUILD_BENCH=OFF) ;;
  fuzz)
    dir=build-fuzz
    what="clang-14, libFuzzer + AddressSanitizer + UndefinedBehaviorSanitizer"
    options=("${fuzz_flags[@]}" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14
             -DCONVEXLOC_FUZZ=ON -DCONVEXLOC_BUILD_TESTS=OFF -DCONVEXLOC_BUILD_CLI=OFF
             -DCONVEXLOC_BUILD_VIEWER=OFF -DCONVEXLOC_BUILD_BENCH=OFF) ;;
  bench)
    dir=build-bench
    what="Release, the benchmarks with GEOS and CGAL"
    options=(-DCMAKE_BUILD_TYPE=Release -DCONVEXLOC_BENCH_PEERS=ON -DCONVEXLOC_BUILD_TESTS=OFF
             -DCONVEXLOC_BUILD_CLI=OFF -DCONVEXLOC_BUILD_VIEWER=OFF) ;;
esac
# clang warns where g++ does not; warnings are errors in the g++ builds, not in the fuzz one
if [[ $variant == fuzz ]]; then werror=OFF; fi
echo "convexloc: configuring $dir/ ($what, warnings as errors: $werror)"
cmake -S . -B "$dir" -G Ninja "${options[@]}" -DCONVEXLOC_WERROR=$werror >/dev/null
echo "convexloc: building $dir/"
cmake --build "$dir" --parallel "$(nproc)"

# the Python module, where Debian's python3 imports it from (plain build only: the sanitized
# and fuzz builds leave it out); `PYTHONPATH=build/python` uses it without installing
if [[ $variant == plain && -d "$dir/python/convexloc" ]]; then
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
  echo "convexloc: installing the Python module for /usr/bin/python3"
  $sudo cmake --install "$dir" --component python >/dev/null
fi
