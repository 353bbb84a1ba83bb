"""locate_xy / locate_xyz against locate on an (M, dims) array, per point, one thread.

    PYTHONPATH=build/python /usr/bin/python3 app/python/examples/columns_speed.py

Each timing is the best of several runs on the same points; the ratio is columns / rows.
"""

import time
from typing import Any, Callable

import numpy as np
import numpy.typing as npt

import convexloc


def best(run: Callable[[], object], repeats: int = 7) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def compare(name: str, locator: Any, points: npt.NDArray[np.float64]) -> None:
    m = len(points)
    columns = [np.ascontiguousarray(points[:, k]) for k in range(points.shape[1])]
    views = [points[:, k] for k in range(points.shape[1])]  # strided views of the rows
    by_columns = locator.locate_xy if points.shape[1] == 2 else locator.locate_xyz
    rows = best(lambda: locator.locate(points, workers=1))
    separate = best(lambda: by_columns(*columns, workers=1))
    strided = best(lambda: by_columns(*views, workers=1))
    stacked = best(lambda: locator.locate(np.column_stack(columns), workers=1))
    print(f"{name:28s} rows {rows / m * 1e9:6.2f} ns/pt   columns {separate / m * 1e9:6.2f} "
          f"({separate / rows:4.2f}x)   strided views {strided / m * 1e9:6.2f} "
          f"({strided / rows:4.2f}x)   column_stack {stacked / m * 1e9:6.2f} "
          f"({stacked / rows:4.2f}x)")


def main() -> None:
    rng = np.random.default_rng(0)
    t = 2 * np.pi * np.arange(1024) / 1024
    polygon = convexloc.Polygon(np.column_stack([np.cos(t), np.sin(t)]))
    points2 = rng.uniform(-1.2, 1.2, size=(4_000_000, 2))
    for cls in (convexloc.PolarLocator, convexloc.SlabLocator):
        compare(f"{cls.__name__}, 1024-gon", cls(polygon), points2)
    cloud = rng.normal(size=(5002, 3))
    hull = convexloc.Polyhedron.hull(cloud / np.linalg.norm(cloud, axis=1)[:, None])
    points3 = rng.uniform(-1.2, 1.2, size=(2_000_000, 3))
    compare(f"CubemapLocator, {hull.face_count} faces", convexloc.CubemapLocator(hull), points3)
    x = rng.uniform(-1.2, 1.2, size=(2000, 1))
    y = rng.uniform(-1.2, 1.2, size=(1, 2000))
    polar = convexloc.PolarLocator(polygon)
    grid = best(lambda: polar.locate_xy(x, y, workers=1))
    print(f"broadcast (2000, 1) x (1, 2000) grid: {grid / x.size / y.size * 1e9:6.2f} ns/pt")


if __name__ == "__main__":
    main()
