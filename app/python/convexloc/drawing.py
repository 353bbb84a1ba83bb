"""Pictures of shapes, subdivisions, classified points and queries, made once as a Scene of
plain primitives in the shape's own coordinates, then drawn by matplotlib (plot, figure) or
written as SVG (svg, the notebooks' _repr_svg_). Everything drawn comes from the locators'
cells(), trace() and locate(); nothing here decides inside or outside."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np
import numpy.typing as npt

from . import LOCATORS_2D, LOCATORS_3D, Location, Polygon, Polyhedron
from .chunks import geo_polygon

__all__ = ["Scene", "scene", "paper_figure", "LOCATION_COLOURS", "count_fill"]

Floats = npt.NDArray[np.float64]

#: the colour of each Location code, for classified points and a trace's answer
LOCATION_COLOURS = {Location.INSIDE: "#2e7d32", Location.BOUNDARY: "#ef8f00",
                    Location.OUTSIDE: "#c62828"}
#: a test's sign: inner side, on the line (plane), outer side
SIGN_COLOURS = {1: "#2e7d32", 0: "#ef8f00", -1: "#c62828"}
#: cells by how many edges (faces) they list: 1, 2, 3, 4 or more
COUNT_FILLS = ("#dbe8f6", "#9dc3e6", "#5b9bd5", "#2e75b6")


def count_fill(count: int) -> str:
    """The fill of a cell listing `count` edges or faces (white for none)."""
    return COUNT_FILLS[min(count, len(COUNT_FILLS)) - 1] if count else "#ffffff"


@dataclass
class Item:
    """One primitive: polygons (closed outlines), a polyline, dots or a text."""

    kind: str
    points: list[Floats]
    fills: list[str] = field(default_factory=list)
    stroke: str = "#404040"
    width: float = 1.0
    size: float = 4.0
    text: str = ""
    label: str = ""
    dashed: bool = False


@dataclass
class Scene:
    """What a picture holds, in the shape's coordinates (y up): a title, primitives in drawing
    order, and legend entries (colour, words)."""

    title: str = ""
    items: list[Item] = field(default_factory=list)
    legend: list[tuple[str, str]] = field(default_factory=list)

    def polygons(self, outlines: Sequence[Any], fills: Sequence[str] | str = "none",
                 stroke: str = "#404040", width: float = 1.0) -> None:
        shapes = [np.asarray(o, dtype=np.float64).reshape(-1, 2) for o in outlines]
        colours = [fills] * len(shapes) if isinstance(fills, str) else list(fills)
        self.items.append(Item("polygons", shapes, colours, stroke, width))

    def line(self, points: Any, stroke: str, width: float = 1.0, dashed: bool = False) -> None:
        self.items.append(Item("line", [np.asarray(points, dtype=np.float64).reshape(-1, 2)],
                               stroke=stroke, width=width, dashed=dashed))

    def dots(self, points: Any, colour: str, size: float = 4.0, label: str = "") -> None:
        self.items.append(Item("dots", [np.asarray(points, dtype=np.float64).reshape(-1, 2)],
                               stroke=colour, size=size, label=label))

    def write(self, at: Any, text: str, size: float = 8.0, colour: str = "#202020") -> None:
        self.items.append(Item("text", [np.asarray(at, dtype=np.float64).reshape(1, 2)],
                               stroke=colour, size=size, text=text))

    def bounds(self) -> tuple[float, float, float, float]:
        """(minx, miny, maxx, maxy) of every finite point drawn."""
        every = [p for item in self.items for p in item.points if len(p)]
        points = np.concatenate(every) if every else np.zeros((1, 2))
        points = points[np.isfinite(points).all(axis=1)]
        if not len(points):
            points = np.zeros((1, 2))
        lo, hi = points.min(axis=0), points.max(axis=0)
        return float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])


# === What each kind of thing draws


def _dims(thing: Any) -> int:
    if isinstance(thing, Polygon) or type(thing) in LOCATORS_2D.values():
        return 2
    if isinstance(thing, Polyhedron) or type(thing) in LOCATORS_3D.values():
        return 3
    raise TypeError("plot takes a convexloc Polygon, Polyhedron or locator (or a Shapely polygon "
                    f"or GeoJSON mapping), got {type(thing).__name__}")


def _cell_counts_legend(scene: Scene, counts: Sequence[int], what: str) -> None:
    for k in sorted(set(min(c, len(COUNT_FILLS)) for c in counts if c)):
        more = "+" if k == len(COUNT_FILLS) else ""
        scene.legend.append((count_fill(k), f"cell listing {k}{more} {what}"))


def _cells_2d(scene: Scene, locator: Any) -> list[Any]:
    cells: list[Any] = locator.cells()
    counts = [len(c["edges"]) for c in cells]
    scene.polygons([c["outline"] for c in cells], [count_fill(k) for k in counts],
                   stroke="#8c8c8c", width=0.5)
    if 0 < len(cells) <= 40:  # the edge count written in each cell, where it can be read
        for cell, k in zip(cells, counts):
            scene.write(np.asarray(cell["outline"]).mean(axis=0), str(k), size=7)
    _cell_counts_legend(scene, counts, "edges")
    if locator.method == "polar":
        (x0, y0), (x1, y1) = locator.box
        scene.polygons([[(x0, y0), (x1, y0), (x1, y1), (x0, y1)]], stroke="#404040")
        scene.dots([locator.centre], "#000000", size=3, label="centre x_T")
    return cells


def _shape_2d(scene: Scene, polygon: Polygon) -> None:
    scene.polygons([polygon.vertices], "none", stroke="#000000", width=2.0)


def _points_2d(scene: Scene, locator: Any, points: Any) -> None:
    xy = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    codes = locator.locate(xy)
    for code, colour in LOCATION_COLOURS.items():
        chosen = xy[codes == code]
        if len(chosen):
            scene.dots(chosen, colour, size=3, label=f"{code.name.lower()} ({len(chosen)})")


def _trace_2d(scene: Scene, locator: Any, cells: list[Any], trace: Any) -> None:
    """The query's steps: its cell, the rays and edges it tested with their signs, the point."""
    point = trace.pop("_point")
    vertices = locator.shape.vertices
    n = len(vertices)
    if 0 <= trace["cell"] < len(cells):
        scene.polygons([cells[trace["cell"]]["outline"]], "#ffe699", stroke="#bf9000", width=1.5)
    apex = trace["apex"]
    for vertex, sign in trace["rays"]:
        scene.line([apex, vertices[vertex]], SIGN_COLOURS[sign], width=1.0, dashed=True)
    for edge, sign in trace["edges"]:
        scene.line([vertices[edge], vertices[(edge + 1) % n]], SIGN_COLOURS[sign], width=3.0)
    if locator.method == "polar":
        scene.line([locator.centre, point], "#404040", width=0.8, dashed=True)
    location = Location(trace["result"])
    scene.dots([point], LOCATION_COLOURS[location], size=7, label=f"query: {location.name}")
    tested = len(trace["edges"])
    scene.title += (f"; query {tuple(float(c) for c in point)}: {trace['location_name']}, "
                    f"{tested} edge test{'s' if tested != 1 else ''}")


# === 3D: the cube map as a net, a polyhedron seen obliquely

# where each cube face (+x, -x, +y, -y, +z, -z) lies on the net: a cross whose strip runs -y,
# +x, +y, -x around z, with +z above and -z below the -y face; each maps normalised (x, y, z)
# on its face to the net by (which coordinate and its sign) across, the same up, and offsets
_NET = {
    0: ((1, 1), (2, 1), (2, 0)),
    1: ((1, -1), (2, 1), (6, 0)),
    2: ((0, -1), (2, 1), (4, 0)),
    3: ((0, 1), (2, 1), (0, 0)),
    4: ((0, 1), (1, 1), (0, 2)),
    5: ((0, 1), (1, -1), (0, -2)),
}


def _on_net(face: int, u: Floats) -> Floats:
    (a, sa), (b, sb), (dx, dy) = _NET[face]
    return np.stack([sa * u[..., a] + dx, sb * u[..., b] + dy], axis=-1)


def _directions_on_net(centre: Any, points: Floats) -> tuple[Floats, npt.NDArray[np.int64]]:
    """Where each point's direction from the centre meets the cube, on the net."""
    d = points - np.asarray(centre)
    axis = np.abs(d).argmax(axis=1)
    big = np.abs(d)[np.arange(len(d)), axis]
    faces = 2 * axis + (d[np.arange(len(d)), axis] < 0)
    u = d / np.where(big > 0, big, 1.0)[:, None]
    out = np.zeros((len(d), 2))
    for face in range(6):
        chosen = faces == face
        out[chosen] = _on_net(face, u[chosen])
    return out, faces


def _net(scene: Scene, locator: Any) -> list[Any]:
    cells: list[Any] = locator.cells()
    if not cells:
        return cells
    centre, half = np.asarray(locator.centre), locator.cube_half_size
    outlines = [_on_net(c["cube_face"], (np.asarray(c["corners"]) - centre) / half)
                for c in cells]
    counts = [len(c["faces"]) for c in cells]
    scene.polygons(outlines, [count_fill(k) for k in counts], stroke="#8c8c8c", width=0.4)
    names = ("+x", "-x", "+y", "-y", "+z", "-z")
    for face, name in enumerate(names):
        scene.polygons([_on_net(face, np.array(_SQUARE[face]))], stroke="#303030", width=1.2)
        scene.write(_on_net(face, np.array(_SQUARE[face])).mean(axis=0), name, size=9,
                    colour="#7f7f7f")
    _cell_counts_legend(scene, counts, "faces")
    return cells


# each cube face's square in normalised coordinates, for its outline on the net
_SQUARE = {
    0: [(1, -1, -1), (1, 1, -1), (1, 1, 1), (1, -1, 1)],
    1: [(-1, -1, -1), (-1, 1, -1), (-1, 1, 1), (-1, -1, 1)],
    2: [(-1, 1, -1), (1, 1, -1), (1, 1, 1), (-1, 1, 1)],
    3: [(-1, -1, -1), (1, -1, -1), (1, -1, 1), (-1, -1, 1)],
    4: [(-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)],
    5: [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1)],
}


def _view(points: Any) -> Floats:
    """Points seen obliquely from above: (screen x, screen y, depth toward the viewer)."""
    yaw, pitch = 0.6, 0.45
    cy, sy, cp, sp = np.cos(yaw), np.sin(yaw), np.cos(pitch), np.sin(pitch)
    turn = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    tilt = np.array([[1, 0, 0], [0, cp, -sp], [0, sp, cp]])
    p = np.asarray(points, dtype=np.float64) @ turn.T @ tilt.T
    return np.stack([p[..., 0], p[..., 2], -p[..., 1]], axis=-1)


def _solid(scene: Scene, polyhedron: Polyhedron) -> None:
    """The triangles seen from outside, far ones first."""
    corners = _view(polyhedron.vertices)
    front = []
    for tri in polyhedron.triangles:
        a, b, c = corners[tri]
        if np.cross(b[:2] - a[:2], c[:2] - a[:2]) > 0:
            front.append((float(corners[tri, 2].mean()), corners[tri, :2]))
    front.sort(key=lambda f: f[0])
    scene.polygons([f[1] for f in front], "#f4b183", stroke="#843c0c", width=0.6)


def _points_3d(scene: Scene, locator: Any, points: Any, on_net: bool) -> None:
    xyz = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    codes = locator.locate(xyz)
    where = _directions_on_net(locator.centre, xyz)[0] if on_net else _view(xyz)[:, :2]
    for code, colour in LOCATION_COLOURS.items():
        chosen = where[codes == code]
        if len(chosen):
            scene.dots(chosen, colour, size=3, label=f"{code.name.lower()} ({len(chosen)})")


def _trace_3d(scene: Scene, locator: Any, cells: list[Any], trace: Any, on_net: bool) -> None:
    point = np.asarray(trace.pop("_point"), dtype=np.float64).reshape(1, 3)
    if on_net:
        key = (trace["cube_face"], trace["level"], trace["cell_i"], trace["cell_j"])
        for cell in cells:
            if (cell["cube_face"], cell["level"], cell["i"], cell["j"]) == key:
                centre, half = np.asarray(locator.centre), locator.cube_half_size
                outline = _on_net(cell["cube_face"], (np.asarray(cell["corners"]) - centre) / half)
                scene.polygons([outline], "#ffe699", stroke="#bf9000", width=1.5)
        where = _directions_on_net(locator.centre, point)[0]
    else:
        where = _view(point)[:, :2]
    location = Location(trace["result"])
    scene.dots(where, LOCATION_COLOURS[location], size=7, label=f"query: {location.name}")
    signs = ", ".join(f"{face}{'+' if s > 0 else '-' if s < 0 else '0'}"
                      for face, s in trace["faces"][:6])
    more = ", ..." if len(trace["faces"]) > 6 else ""
    tests = f"faces tested [{signs}{more}]" if trace["faces"] else "no face test"
    if trace["by_radius"]:
        tests = "decided by the cell's radii"
    scene.title += f"; query {tuple(float(c) for c in point[0])}: {trace['location_name']}, {tests}"


# === The entry point


def scene(thing: Any, points: Any = None, trace: Any = None) -> Scene:
    """The Scene of a shape or locator (a Shapely polygon or GeoJSON mapping is made a
    Polygon), with `points` classified and `trace` (a point, or a dict from trace()) drawn."""
    thing = geo_polygon(thing)
    dims = _dims(thing)
    locator: Any = thing
    if isinstance(thing, Polygon):
        locator = LOCATORS_2D["polar"](thing)
    elif isinstance(thing, Polyhedron):
        locator = LOCATORS_3D["cubemap"](thing)
    shape = locator.shape
    made = Scene(title=f"{locator.method} over {_describe(shape)}")
    if trace is not None and not isinstance(trace, dict):
        point = trace
        trace = dict(locator.trace(point))
        trace["_point"] = point
    elif trace is not None:
        raise ValueError("trace= takes the point to trace (its dict does not name the point)")
    if dims == 2:
        cells = _cells_2d(made, locator) if thing is locator else []
        _shape_2d(made, shape)
        if points is not None:
            _points_2d(made, locator, points)
        if trace is not None:
            _trace_2d(made, locator, cells, trace)
        return made
    on_net = thing is locator and locator.method == "cubemap" and locator.centre is not None
    cells = _net(made, locator) if on_net else []
    if not on_net:
        _solid(made, shape)
    if points is not None:
        _points_3d(made, locator, points, on_net)
    if trace is not None:
        _trace_3d(made, locator, cells, trace, on_net)
    return made


def _describe(shape: Any) -> str:
    if isinstance(shape, Polygon):
        return f"a {len(shape)}-gon"
    return f"a polyhedron of {shape.face_count} triangles"


# === The paper's figures


def _figure_polygon() -> Polygon:
    t = np.sort(np.random.default_rng(6).uniform(0, 2 * np.pi, 11))
    return Polygon(np.column_stack([1.6 * np.cos(t), np.sin(t)]))


def paper_figure(number: int) -> Scene:
    """The Scene of the paper's figure `number` (1 to 7), drawn by the same code as scene()."""
    polygon = _figure_polygon()
    probe = (0.55, 0.35)
    captions = {
        1: ("halfplane", 0, "Fig. 1: point-in-convex polygon, O(N): every half-plane"),
        2: ("wedge", 0, "Fig. 2: O(lg N): wedges from x0, a binary search"),
        3: ("slab", 0, "Fig. 3: O(lg N): slabs and their active edges"),
        4: ("uniform", 16, "Fig. 4: O(1): uniform slabs, eq. (4) picks one"),
        6: ("polar", 4, "Fig. 6: polar slabs decomposition of a convex polygon"),
    }
    if number in captions:
        method, resolution, caption = captions[number]
        cls = LOCATORS_2D[method]
        locator = cls(polygon, resolution) if resolution else cls(polygon)
        made = scene(locator, trace=probe)
        made.title = caption
        return made
    if number == 5:
        # two vertices 0.05 apart in y: uniform slabs as thin as that gap, as the paper's rule
        octagon = np.array([[1, 0], [0.7, 0.7], [0, 1], [-0.7, 0.75], [-1, 0], [-0.7, -0.7],
                            [0, -1], [0.7, -0.7]])
        gap = 0.05
        made = scene(LOCATORS_2D["uniform"](Polygon(octagon), int(round(2 / gap))))
        made.line([(-1.2, 0.7), (1.2, 0.7)], "#c00000", dashed=True)
        made.line([(-1.2, 0.75), (1.2, 0.75)], "#c00000", dashed=True)
        made.title = f"Fig. 5: the slab thickness is the smallest y-gap ({gap})"
        return made
    if number == 7:
        cloud = np.random.default_rng(7).normal(size=(40, 3)) * [1.0, 0.8, 0.6]
        made = scene(LOCATORS_3D["cubemap"](Polyhedron.hull(cloud), 4))
        made.title = 'Fig. 7: "spherical" decomposition of a convex polyhedron, as a cube net'
        return made
    raise ValueError(f"the paper has figures 1 to 7, got {number}")
