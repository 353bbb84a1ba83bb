#!/usr/bin/env bash
# --check and --notes without a display: the shipped lecture is clean (exit 0, one OK line);
# a lecture with three mistakes gives three FILE:LINE lines naming the bad values and exit 1;
# --notes prints every slide's number, title and notes.
# usage: lecture_check.sh VIEWER LECTURE OUTDIR
set -euo pipefail
viewer=$1 lecture=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
env -u DISPLAY "$viewer" --check "$lecture" >"$out/clean.txt"
[[ $(wc -l <"$out/clean.txt") -eq 1 ]] || { cat "$out/clean.txt"; exit 1; }
grep -q ": OK, [0-9]* slides, [0-9]* with notes" "$out/clean.txt"
printf 'slide One\nmethd polar\nslide Two\nprobe 1.2,0.5x\nnotes Say two.\nslide Three\nshape gone.txt\nslide Four\nspray 0\n' \
  >"$out/bad.lecture"
if env -u DISPLAY "$viewer" --check "$out/bad.lecture" >"$out/bad.txt"; then
  echo "--check passed a lecture with three mistakes" >&2
  exit 1
fi
grep -qx "$out/bad.lecture:2: unknown key 'methd' (did you mean method?)" "$out/bad.txt"
grep -q "^$out/bad.lecture:4: probe needs .*'0.5x' is not a number" "$out/bad.txt"
grep -q "^$out/bad.lecture:7: shape: file 'gone.txt' not found (looked for .*gone.txt" "$out/bad.txt"
[[ $(grep -c "^$out/bad.lecture:[0-9]" "$out/bad.txt") -eq 3 ]]
env -u DISPLAY "$viewer" --notes "$out/bad.lecture" >"$out/notes.txt" 2>/dev/null || true
grep -qx "2. Two" "$out/notes.txt"
grep -qx "   Say two." "$out/notes.txt"
grep -qx "4. Four" "$out/notes.txt"
env -u DISPLAY "$viewer" --notes "$lecture" >"$out/shipped-notes.txt"
echo "check: clean and three problems found; notes: $(grep -c '^[0-9]*\. ' "$out/shipped-notes.txt") slides"
