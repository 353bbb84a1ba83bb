#!/usr/bin/env python3
"""The CAD family's table from one run of convexloc-bench (JSON out), as Markdown.

Usage: convexloc-bench --benchmark_filter=CadFamily3D --benchmark_out=cad.json
       tests/bench/cad_family_table.py cad.json > docs/bench/cad-family.md
(or the console output saved to a file, several files in a row)

Each row: a cylinder of N sides and height h (in radii), turned by odd angles, at the origin
or moved to 10^6, rounded to float32 and read (as its hull where rounding folds it); its
cube map's ns per point (CPU time, one point per call) beside a geodesic sphere of as many
triangles from the same run, the ratio, the build time and how many cells are fans.
"""
import json
import sys


def console_runs(text):
    """The runs of convexloc-bench's console output: name, times in ns, counters."""
    runs = []
    for line in text.splitlines():
        parts = line.split()
        if len(parts) < 6 or not parts[0].startswith("CadFamily3D/") or parts[2] != "ns":
            continue
        run = {"name": parts[0], "cpu_time": float(parts[3])}
        for item in parts[6:]:
            key, _, value = item.partition("=")
            if key == "items_per_second":
                continue
            scale = {"k": 1e3, "m": 1e-3, "M": 1e6, "u": 1e-6}.get(value[-1:], 1)
            run[key] = float(value[:-1] if scale != 1 else value) * scale
        runs.append(run)
    return runs


def load(path):
    text = open(path).read()
    if text.lstrip().startswith("{"):
        return [r for r in json.loads(text)["benchmarks"]
                if r.get("run_type", "iteration") == "iteration"]
    return console_runs(text)


def main(paths):
    by_name = {r["name"]: r for path in paths for r in load(path)}
    print("| sides | height (radii) | placed | read as | triangles | cubemap ns | sphere ns "
          "| ratio | build s | fan cells |")
    print("|---:|---:|---|---|---:|---:|---:|---:|---:|---:|")
    for name, r in by_name.items():
        if not name.startswith("CadFamily3D/cubemap/"):
            continue
        sides, tenths, moved = name.split("/")[2:5]
        sphere = by_name.get(name.replace("/cubemap/", "/geodesic/"))
        if sphere is None:
            continue
        ratio = r["cpu_time"] / sphere["cpu_time"]
        print(f"| {sides} | {int(tenths) / 10:g} | {'moved to 10^6' if moved == '1' else 'origin'} "
              f"| {'hull' if r.get('hull') else 'mesh'} | {int(r['triangles'])} "
              f"| {r['cpu_time']:.1f} | {sphere['cpu_time']:.1f} | {ratio:.2f}x "
              f"| {r['build_s']:.3f} | {int(r.get('sectors', 0))} |")


if __name__ == "__main__":
    main(sys.argv[1:])
