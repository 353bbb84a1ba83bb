"""Turns convexloc-bench JSON into a Markdown report (the speed targets checked, then every
family as a table of ns per point) and gnuplot data for the log-log plots."""
import collections
import json
import platform
import sys


def load(path):
    """(family, method) -> {size: ns per item}, and the run's context. With repetitions,
    each benchmark's fastest: on a shared machine the slower ones measure the neighbours."""
    data = json.load(open(path))
    rows = collections.defaultdict(dict)
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" or not b.get("items_per_second"):
            continue
        parts = b["name"].split("/")
        threads = next((p.split(":")[1] for p in parts if p.startswith("threads:")), None)
        if parts[0] in ("Stream", "Stream3D"):
            family, method, size = "Stream", "stream" + parts[0][6:].replace("3D", " 3D"), int(parts[1])
        else:
            family, method, size = parts[0], parts[1], int(parts[2])
        if threads:
            method = f"{method} ({threads} thr)"
        ns = 1e9 / b["items_per_second"]
        row = rows[(family, method)]
        row[size] = min(ns, row.get(size, ns))
    ctx = dict(data.get("context", {}))
    ctx["repetitions"] = max((b.get("repetitions", 1) for b in data["benchmarks"]), default=1)
    return rows, ctx


# the order rows and plot series take (a run that interleaves at random lists the
# benchmarks in no fixed order)
ORDER = ["halfplane", "wedge", "slab", "uniform", "polar", "halfspace", "walk", "cubemap",
         "geos", "cgal", "stream", "stream 3D"]


def method_key(method):
    name, _, threads = method.partition(" (")
    return (ORDER.index(name) if name in ORDER else len(ORDER), name, threads)


def reps_text(ctx):
    reps = ctx.get("repetitions", 1)
    if reps <= 1:
        return ""
    return (f", each figure the fastest of its {reps} repetitions, which the run interleaves "
            "at random")


def cpu_model():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def ns(rows, family, method, size):
    return rows.get((family, method), {}).get(size)


class Ratios:
    """Measured ratios against limits, as (what, measured text, verdict) rows; `words` are
    the verdicts within and beyond the limit, `limit_name` what the limit is called."""

    def __init__(self, words, limit_name=""):
        self.rows, self.words, self.limit_name = [], words, limit_name

    def add(self, what, a, b, limit, at_most):
        """a / b against the limit: at most it (growth), or at least it (a speed-up)"""
        if a is None or b is None:
            self.rows.append((what, "not measured", "—"))
            return
        r = a / b
        if at_most:
            shown = f"{r:.2f}x ({self.limit_name}at most {limit}x)"
        else:
            shown = f"{r:.1f}x ({self.limit_name}at least {limit}x)"
        holds = r <= limit if at_most else r >= limit
        self.rows.append((what, f"{a:.3g} / {b:.3g} ns = {shown}", self.words[0 if holds else 1]))


def one_thread(rows, ratios, path, polar, cubemap):
    """The floors on 1 thread, with convexloc's figures from `polar` and `cubemap`, each a
    (family, method) pair, and `path` naming them; the peers are timed one point per call."""
    big, small = 1 << 20, 8
    ratios.add(f"polar, {path}: N = 2^20 against N = 8",
               ns(rows, *polar, big), ns(rows, *polar, small), 4, True)
    ratios.add(f"polar, {path}: against wedge at N = 16384",
               ns(rows, "Locate2D", "wedge", 16384), ns(rows, *polar, 16384), 5, False)
    ratios.add(f"polar, {path}: against GEOS prepared contains at N = 16384",
               ns(rows, "Locate2D", "geos", 16384), ns(rows, *polar, 16384), 30, False)
    ratios.add(f"cubemap, {path}: F = 10^6 against F = 100",
               ns(rows, *cubemap, 1000000), ns(rows, *cubemap, 100), 4, True)
    for f in (100000, 1000000):
        ratios.add(f"cubemap, {path}: against CGAL Side_of_triangle_mesh at F = 10^{len(str(f)) - 1}",
                   ns(rows, "Locate3D", "cgal", f), ns(rows, *cubemap, f), 50, False)


def floors(rows):
    """The speed targets, each as (what, measured text, verdict)."""
    ratios = Ratios(("holds", "FAILS"))
    # The floors "polar 1 thread" and "cubemap 1 thread" are read as the method's throughput
    # on one thread over many points: the batch on 1 thread (what `classify` runs), against
    # the peers' one-call-per-point loops (all their APIs offer). The same ratios for
    # convexloc's one point per call follow as information (per_call).
    one_thread(rows, ratios, "1 thread", ("Batch2D", "polar (1 thr)"), ("Batch3D", "cubemap (1 thr)"))
    # the streaming limit as the targets define it (two doubles in, a byte out); for 3D also
    # against streaming its own 3-double points, shown beside it, not instead of it
    stream = ns(rows, "Stream", "stream (2 thr)", 10000000)
    stream3 = ns(rows, "Stream", "stream 3D (2 thr)", 10000000)
    for family, method, sizes, limits in (
            ("Batch2D", "polar", (8, 64, 1024, 4096), ((stream, "the streaming limit"),)),
            ("Batch3D", "cubemap", (100, 1000, 10000),
             ((stream, "the streaming limit"),
              (stream3, "streaming 3-double points (information)")))):
        worst = max(((ns(rows, family, f"{method} (2 thr)", s) or 0, s) for s in sizes))
        for limit, name in limits:
            ratios.add(f"{method}, batch 2 threads, worst size up to {sizes[-1]} ({worst[1]}) "
                       f"against {name} (2 threads, 10^7 points)",
                       worst[0] or None, limit, 4, True)
    out = ratios.rows
    for family, method, size, label in (("Build2D", "polar", 1 << 20, "polar build at N = 2^20"),
                                        ("Build3D", "cubemap", 1000000, "cubemap build at F = 10^6")):
        per = ns(rows, family, method, size)
        if per is None:
            out.append((label, "not measured", "—"))
        else:
            seconds = per * size / 1e9
            out.append((label, f"{seconds:.3f} s (under 1 s)", "holds" if seconds < 1 else "FAILS"))
    return out


def per_call(rows):
    """The 1-thread floors' ratios for one point per call (locate(p) in a plain loop), as
    information: (what, measured text, whether the floor's ratio is reached)."""
    ratios = Ratios(("reached", "not reached"), "floor: ")
    one_thread(rows, ratios, "one point per call", ("Locate2D", "polar"), ("Locate3D", "cubemap"))
    return ratios.rows


def main(path, out):
    rows, ctx = load(path)
    lines = [f"Run of {ctx.get('date', '?')} on {ctx.get('host_name', platform.node())}: "
             f"{cpu_model()}, {ctx.get('num_cpus', '?')} CPUs, load average at the start "
             f"{', '.join(f'{x:.2f}' for x in ctx.get('load_avg', [])) or '?'}; "
             "ns per point (lower is better), one run of `tests/bench/report`"
             f"{reps_text(ctx)}.", ""]
    lines += ["### The speed targets, from this run", "",
              "| floor | measured | verdict |", "|---|---|---|"]
    lines += [f"| {w} | {m} | {v} |" for w, m, v in floors(rows)]
    lines += ["", "### The same ratios for one point per call (information)", "",
              "| ratio | measured | the floor's ratio |", "|---|---|---|"]
    lines += [f"| {w} | {m} | {v} |" for w, m, v in per_call(rows)]
    lines.append("")
    for family in ["Locate2D", "Batch2D", "Build2D", "Locate3D", "Batch3D", "Build3D", "Stream"]:
        methods = sorted((m for (f, m) in rows if f == family), key=method_key)
        if not methods:
            continue
        sizes = sorted({s for m in methods for s in rows[(family, m)]})
        lines += [f"### {family}", "", "| method | " + " | ".join(str(s) for s in sizes) + " |",
                  "|---|" + "--:|" * len(sizes)]
        for m in methods:
            cells = [f"{rows[(family, m)][s]:.3g}" if s in rows[(family, m)] else "—" for s in sizes]
            lines.append(f"| {m} | " + " | ".join(cells) + " |")
        lines.append("")
    open(f"{out}/report.md", "w").write("\n".join(lines))
    # the plots: one point per call for every method, and the 1-thread batch of the O(1) ones
    for dim, batch in (("2D", "polar (1 thr)"), ("3D", "cubemap (1 thr)")):
        series = [(m, rows[(f, m)]) for (f, m) in sorted(rows, key=lambda k: method_key(k[1]))
                  if f == f"Locate{dim}"]
        if (f"Batch{dim}", batch) in rows:
            series.append((batch.replace("(1 thr)", "batch"), rows[(f"Batch{dim}", batch)]))
        if not series:
            continue
        with open(f"{out}/locate_{dim}.dat", "w") as f:
            for name, values in series:
                f.write(f'"{name}"\n')
                for s in sorted(values):
                    f.write(f"{s} {values[s]}\n")
                f.write("\n\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
