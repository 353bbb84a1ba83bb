"""Turns convexloc-bench JSON into a Markdown report (the issue's floors checked, then every
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


def floors(rows):
    """The issue's floors, each as (what, measured text, verdict)."""
    def ns(family, method, size):
        return rows.get((family, method), {}).get(size)

    out = []

    def ratio(what, a, b, limit, at_most):
        """a / b against the limit: at most it (growth), or at least it (a speed-up)"""
        if a is None or b is None:
            out.append((what, "not measured", "—"))
            return
        r = a / b
        shown = f"{r:.2f}x (at most {limit}x)" if at_most else f"{r:.1f}x (at least {limit}x)"
        holds = r <= limit if at_most else r >= limit
        out.append((what, f"{a:.3g} / {b:.3g} ns = {shown}", "holds" if holds else "FAILS"))

    def ratio_at_most(what, a, b, limit):
        ratio(what, a, b, limit, True)

    def ratio_at_least(what, slow, fast, limit):
        ratio(what, slow, fast, limit, False)

    # The floors "polar 1 thread" and "cubemap 1 thread" are read as the method's throughput
    # on one thread over many points: the batch on 1 thread (what `classify` runs), against
    # the peers' one-call-per-point loops (all their APIs offer). The same ratios for
    # convexloc's one point per call follow as information, under their own heading.
    big, small = 1 << 20, 8
    ratio_at_most("polar, 1 thread: N = 2^20 against N = 8",
                  ns("Batch2D", "polar (1 thr)", big), ns("Batch2D", "polar (1 thr)", small), 4)
    ratio_at_least("polar, 1 thread, against wedge at N = 16384",
                   ns("Locate2D", "wedge", 16384), ns("Batch2D", "polar (1 thr)", 16384), 5)
    ratio_at_least("polar, 1 thread, against GEOS prepared contains at N = 16384",
                   ns("Locate2D", "geos", 16384), ns("Batch2D", "polar (1 thr)", 16384), 30)
    ratio_at_most("cubemap, 1 thread: F = 10^6 against F = 100",
                  ns("Batch3D", "cubemap (1 thr)", 1000000), ns("Batch3D", "cubemap (1 thr)", 100), 4)
    for f in (100000, 1000000):
        ratio_at_least(f"cubemap, 1 thread, against CGAL Side_of_triangle_mesh at "
                       f"F = 10^{len(str(f)) - 1}",
                       ns("Locate3D", "cgal", f), ns("Batch3D", "cubemap (1 thr)", f), 50)
    # the streaming limit as the issue defines it (two doubles in, a byte out); for 3D also
    # against streaming its own 3-double points, shown beside it, not instead of it
    stream = ns("Stream", "stream (2 thr)", 10000000)
    stream3 = ns("Stream", "stream 3D (2 thr)", 10000000)
    for family, method, sizes, limits in (
            ("Batch2D", "polar", (8, 64, 1024, 4096), ((stream, "the streaming limit"),)),
            ("Batch3D", "cubemap", (100, 1000, 10000),
             ((stream, "the streaming limit"),
              (stream3, "streaming 3-double points (information)")))):
        worst = max(((ns(family, f"{method} (2 thr)", s) or 0, s) for s in sizes))
        for limit, name in limits:
            ratio_at_most(f"{method}, batch 2 threads, worst size up to {sizes[-1]} ({worst[1]}) "
                          f"against {name} (2 threads, 10^7 points)",
                          worst[0] or None, limit, 4)
    for family, method, size, label in (("Build2D", "polar", big, "polar build at N = 2^20"),
                                        ("Build3D", "cubemap", 1000000, "cubemap build at F = 10^6")):
        per = ns(family, method, size)
        if per is None:
            out.append((label, "not measured", "—"))
        else:
            seconds = per * size / 1e9
            out.append((label, f"{seconds:.3f} s (under 1 s)", "holds" if seconds < 1 else "FAILS"))
    return out


def per_call(rows):
    """The 1-thread floors' ratios for one point per call (locate(p) in a plain loop), as
    information: (what, measured text, whether the floor's ratio is reached)."""
    def ns(family, method, size):
        return rows.get((family, method), {}).get(size)

    out = []

    def ratio(what, a, b, limit, at_most):
        if a is None or b is None:
            out.append((what, "not measured", "—"))
            return
        r = a / b
        shown = f"{r:.2f}x (floor: at most {limit}x)" if at_most else f"{r:.1f}x (floor: at least {limit}x)"
        reached = r <= limit if at_most else r >= limit
        out.append((what, f"{a:.3g} / {b:.3g} ns = {shown}", "reached" if reached else "not reached"))

    ratio("polar: N = 2^20 against N = 8", ns("Locate2D", "polar", 1 << 20), ns("Locate2D", "polar", 8), 4, True)
    ratio("polar against wedge at N = 16384", ns("Locate2D", "wedge", 16384), ns("Locate2D", "polar", 16384), 5, False)
    ratio("polar against GEOS prepared contains at N = 16384",
          ns("Locate2D", "geos", 16384), ns("Locate2D", "polar", 16384), 30, False)
    ratio("cubemap: F = 10^6 against F = 100",
          ns("Locate3D", "cubemap", 1000000), ns("Locate3D", "cubemap", 100), 4, True)
    for f in (100000, 1000000):
        ratio(f"cubemap against CGAL Side_of_triangle_mesh at F = 10^{len(str(f)) - 1}",
              ns("Locate3D", "cgal", f), ns("Locate3D", "cubemap", f), 50, False)
    return out


def main(path, out):
    rows, ctx = load(path)
    lines = [f"Run of {ctx.get('date', '?')} on {ctx.get('host_name', platform.node())}: "
             f"{cpu_model()}, {ctx.get('num_cpus', '?')} CPUs, load average at the start "
             f"{', '.join(f'{x:.2f}' for x in ctx.get('load_avg', [])) or '?'}; "
             "ns per point (lower is better), one run of `tests/bench/report`"
             f"{reps_text(ctx)}.", ""]
    lines += ["### The issue's floors, from this run", "",
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
