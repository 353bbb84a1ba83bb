#!/usr/bin/env bash
# Installs what convexloc needs from Debian's packages (only what is missing), then
# configures and builds it (Release) in build/. Usage: scripts/setup.sh [--werror]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake ninja-build g++ pkg-config libgmp-dev libqhull-dev libcli11-dev libgtest-dev
          libbenchmark-dev libglfw3-dev libglm-dev libimgui-dev libstb-dev python3-glad
          xvfb xauth libgl1-mesa-dri)
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

werror=OFF
if [[ "${1:-}" == "--werror" || -n "${CI:-}" ]]; then werror=ON; fi
echo "convexloc: configuring build/ (Release, warnings as errors: $werror)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCONVEXLOC_WERROR=$werror >/dev/null
echo "convexloc: building"
cmake --build build --parallel "$(nproc)"
