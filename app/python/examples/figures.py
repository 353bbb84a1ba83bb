#!/usr/bin/python3
"""The paper's Fig. 6 (polar slabs of a convex polygon) and Fig. 7 (the "spherical"
subdivision of a convex polyhedron, mapped onto a cube) drawn from the locators' cells().

Run it as a script or cell by cell in a notebook:

    python3 app/python/examples/figures.py [OUTPUT_DIR]

With matplotlib installed it draws with matplotlib (PNG and SVG); without it, it writes the
SVG itself. Either way the geometry comes from convexloc alone: PolarLocator.cells() gives
each polar cell's outline and the edges it lists, CubemapLocator.cells() each cube-map
cell's square on the cube around the centre and the faces it lists.
"""

import sys
from pathlib import Path
from typing import Any, Protocol, Sequence, Union

import numpy as np
import numpy.typing as npt

import convexloc

# a cell listing one edge (face) is pale; one listing two or more, where a vertex (an edge
# of the polyhedron) falls inside, is darker
FILLS = ("#dbe8f6", "#9dc3e6", "#5b9bd5", "#2e75b6")


Points = Any  # an (N, 2) array or a sequence of (x, y)
Point = Union[Sequence[float], npt.NDArray[np.float64]]
Box = tuple[tuple[float, float], tuple[float, float]]


def fill_for(count: int) -> str:
    return FILLS[min(count, len(FILLS)) - 1] if count else "#ffffff"


# === Two ways to draw the same primitives


class Canvas(Protocol):
    """What both canvases draw."""

    def polygon(self, points: Points, fill: str = "none", stroke: str = "#404040",
                width: float = 0.5, alpha: float = 1.0) -> None: ...

    def dot(self, p: Point, colour: str = "#c00000") -> None: ...

    def save(self, path: Path, title: str) -> list[Path]: ...


class SvgCanvas:
    """Polygons, lines and dots in an SVG file, y up, scaled to fit `bounds`."""

    def __init__(self, bounds: Box, size: int = 640, margin: int = 20) -> None:
        (self.x0, self.y0), (x1, y1) = bounds
        self.scale = (size - 2 * margin) / max(x1 - self.x0, y1 - self.y0)
        self.margin = margin
        self.items: list[str] = []
        self.width = round((x1 - self.x0) * self.scale) + 2 * margin
        self.height = round((y1 - self.y0) * self.scale) + 2 * margin

    def _xy(self, p: Point) -> tuple[float, float]:
        return (self.margin + (p[0] - self.x0) * self.scale,
                self.height - self.margin - (p[1] - self.y0) * self.scale)

    def polygon(self, points: Points, fill: str = "none", stroke: str = "#404040",
                width: float = 0.5, alpha: float = 1.0) -> None:
        text = " ".join("%.2f,%.2f" % self._xy(p) for p in points)
        self.items.append(f'<polygon points="{text}" fill="{fill}" fill-opacity="{alpha}" '
                          f'stroke="{stroke}" stroke-width="{width}"/>')

    def dot(self, p: Point, colour: str = "#c00000") -> None:
        x, y = self._xy(p)
        self.items.append(f'<circle cx="{x:.2f}" cy="{y:.2f}" r="3" fill="{colour}"/>')

    def save(self, path: Path, title: str) -> list[Path]:
        body = "\n".join(self.items)
        Path(path).write_text(
            f'<svg xmlns="http://www.w3.org/2000/svg" width="{self.width}" height="{self.height}">\n'
            f"<title>{title}</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
            f"{body}\n</svg>\n")
        return [path]


class MatplotlibCanvas:
    """The same primitives on a matplotlib figure."""

    def __init__(self, bounds: Box) -> None:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        self.plt = plt
        self.figure, self.axes = plt.subplots(figsize=(6.4, 6.4))
        self.axes.set_aspect("equal")
        self.axes.axis("off")
        (x0, y0), (x1, y1) = bounds
        self.axes.set_xlim(x0, x1)
        self.axes.set_ylim(y0, y1)

    def polygon(self, points: Points, fill: str = "none", stroke: str = "#404040",
                width: float = 0.5, alpha: float = 1.0) -> None:
        from matplotlib.patches import Polygon
        face = "none" if fill == "none" else fill
        self.axes.add_patch(Polygon(np.asarray(points), closed=True, facecolor=face,
                                    alpha=None if fill == "none" else alpha,
                                    edgecolor=stroke, linewidth=width))

    def dot(self, p: Point, colour: str = "#c00000") -> None:
        self.axes.plot([p[0]], [p[1]], "o", color=colour, markersize=4)

    def save(self, path: Path, title: str) -> list[Path]:
        self.axes.set_title(title)
        png = Path(path).with_suffix(".png")
        self.figure.savefig(path)
        self.figure.savefig(png, dpi=150)
        self.plt.close(self.figure)
        return [path, png]


def canvas(bounds: Box, use_matplotlib: bool) -> Canvas:
    if use_matplotlib:
        try:
            return MatplotlibCanvas(bounds)
        except ImportError:
            pass
    return SvgCanvas(bounds)


def padded(lo: Sequence[float], hi: Sequence[float], pad: float = 0.05) -> Box:
    low, high = np.asarray(lo, float), np.asarray(hi, float)
    d = (high - low).max() * pad
    return ((float(low[0] - d), float(low[1] - d)), (float(high[0] + d), float(high[1] + d)))


# === Fig. 6: polar slabs


def figure6(path: Path, use_matplotlib: bool = True) -> list[Path]:
    """The polar cells of a convex polygon, filled by the number of edges each lists."""
    t = np.sort(np.random.default_rng(6).uniform(0, 2 * np.pi, 11))
    polygon = convexloc.Polygon(np.column_stack([1.6 * np.cos(t), np.sin(t)]))
    polar = convexloc.PolarLocator(polygon, resolution=4)
    lo, hi = polar.box
    draw = canvas(padded(lo, hi), use_matplotlib)
    for cell in polar.cells():
        draw.polygon(cell["outline"], fill=fill_for(len(cell["edges"])), stroke="#7f7f7f")
    draw.polygon([lo, (hi[0], lo[1]), hi, (lo[0], hi[1])], stroke="#404040", width=1.0)
    draw.polygon(polygon.vertices, stroke="#000000", width=2.0)
    draw.dot(polar.centre)
    return draw.save(path, "Fig. 6: polar slabs decomposition of a convex polygon")


# === Fig. 7: the cube map


def view(points: npt.ArrayLike, yaw: float = 0.6,
         pitch: float = 0.45) -> npt.NDArray[np.float64]:
    """Points seen obliquely from above: turned by `yaw` about z, tilted by `pitch` toward the
    viewer, who looks along +y; returns (screen x, screen y = up, depth toward the viewer)."""
    cy, sy, cp, sp = np.cos(yaw), np.sin(yaw), np.cos(pitch), np.sin(pitch)
    turn = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    tilt = np.array([[1, 0, 0], [0, cp, -sp], [0, sp, cp]])
    p = np.asarray(points, dtype=np.float64) @ turn.T @ tilt.T
    return np.stack([p[..., 0], p[..., 2], -p[..., 1]], axis=-1)


def figure7(path: Path, use_matplotlib: bool = True) -> list[Path]:
    """The cube-map cells around the centre of a convex polyhedron, filled by the faces each
    lists: the far cube faces behind the polyhedron, the near ones outlined in front."""
    cloud = np.random.default_rng(7).normal(size=(40, 3)) * [1.0, 0.8, 0.6]
    polyhedron = convexloc.Polyhedron.hull(cloud)
    cubemap = convexloc.CubemapLocator(polyhedron, resolution=4)
    cells = cubemap.cells()
    screen = [view(c["corners"]) for c in cells]
    centre = view(np.array(cubemap.centre))
    flat = np.concatenate(screen)[:, :2]
    draw = canvas(padded(flat.min(axis=0), flat.max(axis=0)), use_matplotlib)
    far = [k for k in range(len(cells)) if screen[k][:, 2].mean() < centre[2]]
    near = [k for k in range(len(cells)) if k not in set(far)]
    for k in sorted(far, key=lambda k: float(screen[k][:, 2].mean())):
        draw.polygon(screen[k][:, :2], fill=fill_for(len(cells[k]["faces"])), stroke="#7f7f7f")
    corners = view(polyhedron.vertices)
    triangles = polyhedron.triangles
    for tri in sorted(triangles, key=lambda t: float(corners[t, 2].mean())):
        a, b, c = corners[tri]
        if np.cross(b[:2] - a[:2], c[:2] - a[:2]) > 0:  # seen from outside
            draw.polygon(corners[tri, :2], fill="#f4b183", stroke="#843c0c", alpha=0.85)
    for k in near:
        draw.polygon(screen[k][:, :2], stroke="#bfbfbf", width=0.3)
    draw.dot(centre[:2])
    return draw.save(path, 'Fig. 7: "spherical" decomposition of a convex polyhedron')


def main(argv: list[str]) -> None:
    """figures.py [--svg] [OUTPUT_DIR]: --svg writes the SVG itself even with matplotlib."""
    flags = [a for a in argv[1:] if a.startswith("--")]
    places = [a for a in argv[1:] if not a.startswith("--")]
    out = Path(places[0]) if places else Path(".")
    out.mkdir(parents=True, exist_ok=True)
    use_matplotlib = "--svg" not in flags
    written = figure6(out / "fig6_polar.svg", use_matplotlib)
    written += figure7(out / "fig7_cubemap.svg", use_matplotlib)
    for path in written:
        print(path)


if __name__ == "__main__":
    main(sys.argv)
