#!/usr/bin/env bash
# Installs, builds (Release) and runs the main job: a short exact classification in the
# terminal, then convexloc-viewer on its default scene. Without a display the viewer says
# so and renders the default scene to convexloc-viewer.png through Xvfb instead.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
bin=build/app/cli/convexloc
shape=assets/hexagon.txt
points=assets/hexagon-points.txt
echo
echo "== convexloc: is each point inside the hexagon in $shape?"
echo "   (polar slabs, the paper's O(1) method; exact: 'boundary' means exactly on an edge)"
echo
printf '   %-28s %s\n' "point (x y)" "answer"
paste <(grep -v '^[[:space:]]*#' "$points" | grep -v '^[[:space:]]*$') \
      <("$bin" classify "$shape" "$points" --method polar) |
  while IFS=$'\t' read -r p answer; do printf '   %-28s %s\n' "$p" "$answer"; done
echo
echo "== every method agrees:"
for m in halfplane wedge slab uniform polar; do
  printf '   %-10s %s\n' "$m" "$("$bin" classify "$shape" "$points" --method "$m" | tr '\n' ' ')"
done
echo
viewer=build/app/viewer/convexloc-viewer
if [[ -x $viewer ]]; then
  echo "== opening convexloc-viewer on its default scene (close the window to finish)"
  exec "$viewer" "$@"
fi
echo "== the viewer was not built (CONVEXLOC_BUILD_VIEWER=OFF); the polar subdivision instead:"
"$bin" info "$shape" --method polar
