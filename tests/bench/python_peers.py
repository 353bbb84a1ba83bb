#!/usr/bin/python3
"""convexloc's Python batch against what Python users reach for, on the same points in one run.

2D, a regular N-gon, points uniform in its bounding box (+5%):
  convexloc   PolarLocator(polygon).locate(points, workers=1)
  shapely     shapely.vectorized.contains(prepared polygon, x, y)   (Shapely 1.8, GEOS)
  numpy       the half-plane test of eq. (1), vectorised over the points, edge by edge
3D, the hull of points on an ellipsoid with about F triangles, points uniform in its box:
  convexloc   CubemapLocator(polyhedron).locate(points, workers=1)
  Delaunay    scipy.spatial.Delaunay(hull vertices).find_simplex(points) >= 0
  numpy       the half-space test of eq. (2), face by face (small F only)

Builds (locator, prepare, triangulation) are not timed; each query time is the best of a few
runs, per point. Slow peers run on a prefix of the points (the table says how many) so that
the whole script stays within about ten minutes on a laptop. Ratios are peer time over
convexloc time: how many times faster convexloc is, one thread against one thread.

Usage: python_peers.py [--build DIR] [--quick] [--out FILE]
  --build DIR  where the module is (DIR/python/convexloc); default: build-bench, then build
  --quick      fewer and smaller sizes (a smoke test)
  --out FILE   also write the Markdown report to FILE
"""

import argparse
import sys
import time
from fractions import Fraction
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


def import_convexloc(build):
    """The module from the build tree asked for, or the first of build-bench/ and build/."""
    for folder in ([Path(build)] if build else [ROOT / "build-bench", ROOT / "build"]):
        if (folder / "python" / "convexloc").is_dir():
            sys.path.insert(0, str(folder / "python"))
            break
    import convexloc
    return convexloc


def best_time(run, repeats):
    """The shortest of `repeats` runs, in seconds."""
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        best = min(best, time.perf_counter() - start)
    return best


def per_point(run, count, budget=1.0):
    """Seconds per point of run(), repeated while the repeats fit the budget (1 to 5)."""
    first = best_time(run, 1)
    repeats = max(1, min(5, int(budget / max(first, 1e-9))))
    return min(first, best_time(run, repeats) if repeats > 1 else first) / count


def prefix_for(cost_per_point, total, budget=2.0):
    """How many points a peer of this estimated cost may take within the budget."""
    return int(min(total, max(10_000, budget / cost_per_point)))


# === 2D


def regular_polygon(n):
    t = 2 * np.pi * np.arange(n) / n
    return np.column_stack([np.cos(t), np.sin(t)])


def halfplane_numpy(vertices, points):
    """Eq. (1) in floating point: inside-or-on iff no edge has the point strictly right."""
    x, y = points[:, 0], points[:, 1]
    a, b = vertices, np.roll(vertices, -1, axis=0)
    inside = np.ones(len(points), dtype=bool)
    for (ax, ay), (bx, by) in zip(a, b):
        inside &= (bx - ax) * (y - ay) - (by - ay) * (x - ax) >= 0
    return inside


def bench_2d(cl, sizes, points_count, rng):
    from shapely.geometry import Polygon as ShapelyPolygon
    from shapely.prepared import prep
    import shapely.vectorized
    rows = []
    for n in sizes:
        vertices = regular_polygon(n)
        points = rng.uniform(-1.05, 1.05, size=(points_count, 2))
        polar = cl.PolarLocator(cl.Polygon(vertices))
        ours = per_point(lambda: polar.locate(points, workers=1), points_count)
        ours_all = per_point(lambda: polar.locate(points, workers=-1), points_count)
        prepared = prep(ShapelyPolygon(vertices))
        m_shapely = prefix_for(3e-6, points_count, budget=3.0)
        x, y = points[:m_shapely, 0].copy(), points[:m_shapely, 1].copy()
        shapely_time = per_point(lambda: shapely.vectorized.contains(prepared, x, y), m_shapely)
        m_numpy = prefix_for(2e-9 * n, points_count, budget=1.0)
        numpy_time = (per_point(lambda: halfplane_numpy(vertices, points[:m_numpy]), m_numpy)
                      if n <= 16384 else None)
        rows.append({"size": n, "ours": ours, "ours_all": ours_all,
                     "shapely": shapely_time, "m_shapely": m_shapely,
                     "numpy": numpy_time, "m_numpy": m_numpy})
        print(f"  2D N={n}: convexloc {ours * 1e9:.1f} ns/pt, shapely {shapely_time * 1e9:.0f}, "
              f"numpy {numpy_time * 1e9 if numpy_time else float('nan'):.0f}", file=sys.stderr)
    return rows


# === 3D


def ellipsoid_hull(cl, faces, rng):
    """The hull of about faces / 2 + 2 points on an ellipsoid: about `faces` triangles."""
    count = max(4, faces // 2 + 2)
    cloud = rng.normal(size=(count, 3))
    cloud = cloud / np.linalg.norm(cloud, axis=1)[:, None] * [1.0, 0.8, 0.6]
    return cl.Polyhedron.hull(cloud)


def halfspace_numpy(polyhedron, points):
    """Eq. (2) in floating point: inside-or-on iff on the inner side of every face plane."""
    v = polyhedron.vertices[polyhedron.triangles]
    normals = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    inside = np.ones(len(points), dtype=bool)
    for normal, a in zip(normals, v[:, 0]):
        inside &= (points - a) @ normal <= 0
    return inside


def bench_3d(cl, sizes, points_count, rng, delaunay_limit):
    from scipy.spatial import Delaunay
    rows = []
    for f in sizes:
        polyhedron = ellipsoid_hull(cl, f, rng)
        lo, hi = np.array(polyhedron.bounds)
        points = rng.uniform(lo - 0.05 * (hi - lo), hi + 0.05 * (hi - lo), size=(points_count, 3))
        cubemap = cl.CubemapLocator(polyhedron)
        ours = per_point(lambda: cubemap.locate(points, workers=1), points_count)
        ours_all = per_point(lambda: cubemap.locate(points, workers=-1), points_count)
        delaunay_time, m_delaunay = None, 0
        if polyhedron.face_count <= delaunay_limit:
            tri = Delaunay(polyhedron.vertices)
            m_delaunay = prefix_for(4e-6, points_count, budget=4.0)
            q = points[:m_delaunay]
            delaunay_time = per_point(lambda: tri.find_simplex(q) >= 0, m_delaunay)
        m_numpy = prefix_for(3e-9 * f, points_count, budget=1.0)
        numpy_time = (per_point(lambda: halfspace_numpy(polyhedron, points[:m_numpy]), m_numpy)
                      if f <= 10_000 else None)
        rows.append({"size": polyhedron.face_count, "ours": ours, "ours_all": ours_all,
                     "delaunay": delaunay_time, "m_delaunay": m_delaunay,
                     "numpy": numpy_time, "m_numpy": m_numpy})
        print(f"  3D F={polyhedron.face_count}: convexloc {ours * 1e9:.1f} ns/pt, Delaunay "
              f"{delaunay_time * 1e9 if delaunay_time else float('nan'):.0f}", file=sys.stderr)
    return rows


# === Exactness: one point each where a peer is wrong


def orient2d_exact(a, b, p):
    det = ((Fraction(b[0]) - Fraction(a[0])) * (Fraction(p[1]) - Fraction(a[1]))
           - (Fraction(b[1]) - Fraction(a[1])) * (Fraction(p[0]) - Fraction(a[0])))
    return (det > 0) - (det < 0)


def exactness_2d(cl):
    """Points on and one ulp beside the edge from (0.1, 0.1) to (0.7, 0.3) of a triangle:
    the exact answer (rational arithmetic) against each method's; two points where
    shapely.vectorized.contains (prepared) is wrong, two where the numpy test is."""
    from shapely.geometry import Polygon as ShapelyPolygon
    from shapely.prepared import prep
    import shapely.vectorized
    tri = np.array([[0.1, 0.1], [0.7, 0.3], [0.2, 0.9]])
    polar = cl.PolarLocator(cl.Polygon(tri))
    prepared = prep(ShapelyPolygon(tri))
    t = np.arange(1, 4000) / 4000
    x, y = 0.1 + t * 0.6, 0.1 + t * 0.2
    points = np.concatenate([np.column_stack([x, y]), np.column_stack([x, np.nextafter(y, 1)]),
                             np.column_stack([x, np.nextafter(y, 0)])])
    ours = polar.locate(points)
    contains = shapely.vectorized.contains(prepared, points[:, 0], points[:, 1])
    halfplane = halfplane_numpy(tri, points)
    wrong = {"shapely": [], "numpy": []}
    for k, p in enumerate(points):
        truth = ("outside", "boundary", "inside")[orient2d_exact(tri[0], tri[1], p) + 1]
        if cl.NAMES[ours[k]] != truth:
            raise AssertionError(f"convexloc wrong at {tuple(p)!r}")
        row = (tuple(p), truth, cl.NAMES[ours[k]], "inside or on" if halfplane[k] else "outside",
               "inside" if contains[k] else "not inside")
        if contains[k] != (truth == "inside") and len(wrong["shapely"]) < 2:
            wrong["shapely"].append(row)
        if halfplane[k] != (truth != "outside") and len(wrong["numpy"]) < 2:
            wrong["numpy"].append(row)
    return wrong["shapely"] + wrong["numpy"]


def outward_side_exact(a, b, c, p):
    """+1 when p is strictly on the outer side of the plane of the counter-clockwise (seen
    from outside) triangle a, b, c, 0 on it, -1 inner; in rational arithmetic."""
    a, b, c, p = ([Fraction(float(t)) for t in v] for v in (a, b, c, p))
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [p[i] - a[i] for i in range(3)]
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (det > 0) - (det < 0)


def exactness_3d(cl, rng):
    """Points a hair outside the faces of a hull: convexloc and exact arithmetic say outside,
    Delaunay.find_simplex (tolerance 100 eps) says inside."""
    from scipy.spatial import Delaunay
    hull = ellipsoid_hull(cl, 1000, rng)
    tri = Delaunay(hull.vertices)
    cubemap = cl.CubemapLocator(hull)
    v = hull.vertices[hull.triangles]
    found = []
    for face, (a, b, c) in enumerate(v):
        centroid = (a + b + c) / 3
        normal = np.cross(b - a, c - a)
        normal /= np.linalg.norm(normal)
        p = centroid + 1e-14 * normal  # outward: triangles are counter-clockwise from outside
        exact = outward_side_exact(a, b, c, p)
        ours = cl.NAMES[int(cubemap.locate([p])[0])]
        theirs = "inside or on" if tri.find_simplex(p[None, :])[0] >= 0 else "outside"
        if exact > 0 and theirs != "outside":
            assert ours == "outside"
            found.append((tuple(p), "outside", ours, theirs))
        if len(found) >= 2 or face > 400:
            break
    return found


# === Report


def ratio(peer, ours):
    return f"{peer / ours:,.0f}x" if peer else "—"


def report(rows2d, rows3d, exact2d, exact3d, points_count):
    out = [f"Points per size: {points_count:,} (a peer marked * ran on the first M of them). "
           "Times per point, one thread; ratios = peer time / convexloc time.", "",
           "| N (2D) | convexloc ns/pt | all cores ns/pt | vs shapely.vectorized | vs numpy half-plane |",
           "|---:|---:|---:|---:|---:|"]
    for r in rows2d:
        star = "*" if r["m_shapely"] < points_count else ""
        nstar = "*" if r["numpy"] and r["m_numpy"] < points_count else ""
        out.append(f"| {r['size']:,} | {r['ours'] * 1e9:.1f} | {r['ours_all'] * 1e9:.1f} | "
                   f"{ratio(r['shapely'], r['ours'])}{star} | {ratio(r['numpy'], r['ours'])}{nstar} |")
    out += ["", "| F (3D) | convexloc ns/pt | all cores ns/pt | vs Delaunay.find_simplex | vs numpy half-space |",
            "|---:|---:|---:|---:|---:|"]
    for r in rows3d:
        star = "*" if r["delaunay"] and r["m_delaunay"] < points_count else ""
        nstar = "*" if r["numpy"] and r["m_numpy"] < points_count else ""
        out.append(f"| {r['size']:,} | {r['ours'] * 1e9:.1f} | {r['ours_all'] * 1e9:.1f} | "
                   f"{ratio(r['delaunay'], r['ours'])}{star} | {ratio(r['numpy'], r['ours'])}{nstar} |")
    out += ["", "Floors (issue 14):"]
    out += floors(rows2d, rows3d)
    out += ["", "Exactness, 2D (triangle (0.1, 0.1), (0.7, 0.3), (0.2, 0.9); truth by rational "
            "arithmetic):", "", "| point | truth | convexloc | numpy half-plane | shapely.vectorized.contains |",
            "|---|---|---|---|---|"]
    out += [f"| ({p[0]!r}, {p[1]!r}) | {t} | {o} | {n} | {s} |" for p, t, o, n, s in exact2d]
    out += ["", "Exactness, 3D (a face centroid moved 1e-14 outward; truth by rational "
            "arithmetic):", "", "| point | truth | convexloc | Delaunay.find_simplex >= 0 |",
            "|---|---|---|---|"]
    out += [f"| ({p[0]!r}, {p[1]!r}, {p[2]!r}) | {t} | {o} | {d} |" for p, t, o, d in exact3d]
    return "\n".join(out) + "\n"


def floors(rows2d, rows3d):
    """The two speed floors, where this run measured them."""
    lines = []
    r = next((r for r in rows2d if r["size"] == 16384), None)
    if r:
        k = r["shapely"] / r["ours"]
        lines.append(f"- 16,384-gon, vs shapely.vectorized on a prepared polygon: {k:,.0f}x "
                     f"(floor 20x: {'met' if k >= 20 else 'NOT met'})")
    r = next((r for r in rows3d if r["delaunay"] and 50_000 <= r["size"] <= 200_000), None)
    if r:
        k = r["delaunay"] / r["ours"]
        lines.append(f"- {r['size']:,}-face hull, vs Delaunay.find_simplex: {k:,.0f}x "
                     f"(floor 20x: {'met' if k >= 20 else 'NOT met'})")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out")
    args = parser.parse_args()
    cl = import_convexloc(args.build)
    rng = np.random.default_rng(2024)
    if args.quick:
        sizes2d, sizes3d, count, limit = [8, 512, 16384], [100, 10_000], 100_000, 10_000
    else:
        sizes2d = [8, 64, 512, 4096, 16384, 1 << 17, 1 << 20]
        sizes3d = [100, 1000, 10_000, 100_000, 1_000_000]
        count, limit = 1_000_000, 200_000
    start = time.perf_counter()
    rows2d = bench_2d(cl, sizes2d, count, rng)
    rows3d = bench_3d(cl, sizes3d, count, rng, limit)
    text = report(rows2d, rows3d, exactness_2d(cl), exactness_3d(cl, rng), count)
    text += f"\n(the whole run: {time.perf_counter() - start:.0f} s)\n"
    print(text)
    if args.out:
        Path(args.out).write_text(text)


if __name__ == "__main__":
    main()
