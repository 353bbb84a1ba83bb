"""Turns convexloc-bench JSON into a Markdown table and gnuplot data (ns per point)."""
import collections
import json
import platform
import sys


def main(path, out):
    data = json.load(open(path))
    ctx = data.get("context", {})
    rows = collections.defaultdict(dict)  # (family, method) -> size -> ns
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        parts = b["name"].split("/")
        ips = b.get("items_per_second")
        if not ips:
            continue
        ns = 1e9 / ips
        if parts[0] == "Stream":
            rows[("Stream", "stream")][int(parts[1])] = ns
            continue
        family, method, size = parts[0], parts[1], int(parts[2])
        threads = next((p.split(":")[1] for p in parts[3:] if p.startswith("threads:")), None)
        if threads:
            method = f"{method} ({threads} thr)"
        rows[(family, method)][size] = ns
    lines = [f"Run {ctx.get('date', '?')} on {ctx.get('host_name', platform.node())}: "
             f"{ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, "
             f"ns per point (lower is better).", ""]
    for family in ["Locate2D", "Batch2D", "Build2D", "Locate3D", "Batch3D", "Build3D", "Stream"]:
        methods = [m for (f, m) in rows if f == family]
        if not methods:
            continue
        sizes = sorted({s for m in methods for s in rows[(family, m)]})
        lines.append(f"### {family}")
        lines.append("")
        lines.append("| method | " + " | ".join(str(s) for s in sizes) + " |")
        lines.append("|---|" + "--:|" * len(sizes))
        for m in methods:
            cells = [f"{rows[(family, m)][s]:.3g}" if s in rows[(family, m)] else "—" for s in sizes]
            lines.append(f"| {m} | " + " | ".join(cells) + " |")
        lines.append("")
    open(f"{out}/report.md", "w").write("\n".join(lines))
    for dim in ["2D", "3D"]:
        family = f"Locate{dim}"
        methods = [m for (f, m) in rows if f == family]
        if not methods:
            continue
        with open(f"{out}/locate_{dim}.dat", "w") as f:
            for m in methods:
                f.write(f'"{m}"\n')
                for s in sorted(rows[(family, m)]):
                    f.write(f"{s} {rows[(family, m)][s]}\n")
                f.write("\n\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
