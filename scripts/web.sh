#!/usr/bin/env bash
# Builds convexloc-viewer as a web page with Debian's emscripten into build-web/site/: a
# static folder (index.html, page.js, convexloc-viewer.js, .wasm and .data, the packed
# shaders, shapes and lectures) that any web server can serve.
# Usage: scripts/web.sh [--serve [PORT]]
#   --serve  then serves build-web/site/ on http://localhost:PORT/ (default 8000)
# Needs Debian's emscripten, dpkg-dev (apt-get source), libboost-dev, libglm-dev,
# libcli11-dev, libstb-dev and fonts-dejavu-core; Dear ImGui 1.86's sources come from
# Debian's imgui source package, fetched through a sources list private to build-web/ (the
# machine's apt configuration is left as it is).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=$root/build-web

serve=0
port=8000
while (($#)); do
  case $1 in
    --serve) serve=1
             if [[ ${2:-} =~ ^[0-9]+$ ]]; then port=$2; shift; fi ;;
    *) echo "usage: scripts/web.sh [--serve [PORT]]" >&2; exit 2 ;;
  esac
  shift
done

for tool in emcc emcmake apt-get dpkg-source; do
  command -v "$tool" >/dev/null || {
    echo "convexloc: $tool is missing (Debian's emscripten and dpkg-dev)" >&2; exit 1; }
done
mkdir -p "$out"

# Emscripten runs its JavaScript tools with the node first on PATH: where that is not
# Debian's, it finds Debian's acorn through NODE_PATH. Its cache, where Debian ships the
# prebuilt system libraries, is mirrored by links into build-web/ so that it is writable.
export NODE_PATH=${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs
if [[ ! -d $out/em-cache ]]; then
  cp -rs /usr/share/emscripten/cache "$out/em-cache.tmp"
  rm -f "$out/em-cache.tmp/cache.lock"
  mv "$out/em-cache.tmp" "$out/em-cache"
fi
export EM_CACHE=$out/em-cache

# Dear ImGui 1.86 from Debian 12's imgui source package, through a private sources list
imgui_dir=$out/imgui
if [[ ! -f $imgui_dir/imgui.cpp ]]; then
  apt_dir=$out/apt
  mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/parts" "$apt_dir/src"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main" \
    >"$apt_dir/sources.list"
  apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o "Dir::Etc::SourceParts=$apt_dir/parts"
            -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
            -o APT::Sandbox::User=root -o Debug::NoLocking=1)
  echo "convexloc: fetching Dear ImGui's sources (Debian's imgui source package)"
  apt-get -qq "${apt_opts[@]}" update
  (cd "$apt_dir/src" && apt-get -qq "${apt_opts[@]}" source imgui=1.86+ds-1 >/dev/null)
  rm -rf "$imgui_dir"
  mv "$apt_dir/src"/imgui-1.86* "$imgui_dir"
  rm -rf "$apt_dir"
fi

# the viewer alone, Release at -O2; exceptions caught (core reports bad input by throwing);
# warnings are not errors here, as in the other clang build (the g++ builds hold that line)
if [[ ! -f $out/CMakeCache.txt ]]; then
  echo "convexloc: configuring build-web/ (emscripten $(emcc -dumpversion))"
  emcmake cmake -S . -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS=-fexceptions "-DCMAKE_EXE_LINKER_FLAGS=-fexceptions -O2" \
    -DCONVEXLOC_IMGUI_SOURCE_DIR="$imgui_dir" \
    -DCONVEXLOC_BUILD_TESTS=OFF -DBUILD_TESTING=OFF -DCONVEXLOC_BUILD_CLI=OFF \
    -DCONVEXLOC_BUILD_PYTHON=OFF -DCONVEXLOC_BUILD_BENCH=OFF >/dev/null
fi
echo "convexloc: building build-web/site/"
cmake --build "$out" --target convexloc-viewer --parallel "$(nproc)"
echo "convexloc: the page is in build-web/site/ ($(du -sh "$out/site" | cut -f1))"

if ((serve)); then
  echo "convexloc: serving http://localhost:$port/ (Ctrl+C stops)"
  exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$out/site"
fi
