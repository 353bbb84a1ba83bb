"""The types of convexloc's values, for annotations: the arrays it takes and gives, and the
dicts trace(), stats() and cells() return (every key is always present)."""

import os
from typing import Any, Mapping, Protocol, TypedDict, Union

import numpy as np
import numpy.typing as npt

from . import Location, Polygon

__all__ = ["ArrayLike", "PathLike", "GeoInterface", "PolygonLike", "Codes", "Floats", "Indices", "Bools",
           "UniformStep", "PolarStep", "Trace2D", "Stats2D", "Cell2D",
           "Trace3D", "Stats3D", "Cell3D"]

#: anything numpy.asarray takes
ArrayLike = npt.ArrayLike
#: a path: str or os.PathLike
PathLike = Union[str, "os.PathLike[str]"]

class GeoInterface(Protocol):
    """Anything with a __geo_interface__ (Shapely geometries, GeoPandas rows, convexloc's shapes)."""

    @property
    def __geo_interface__(self) -> Mapping[str, Any]: ...


#: what every function and class taking a polygon takes: a Polygon, an object with a Polygon
#: __geo_interface__ (a Shapely polygon), a GeoJSON mapping (Polygon, Feature, one-part
#: MultiPolygon; z dropped), or the (N, 2) vertices
PolygonLike = Union[Polygon, GeoInterface, Mapping[str, Any], ArrayLike]
#: the int8 Location codes locate() returns
Codes = npt.NDArray[np.int8]
#: coordinates
Floats = npt.NDArray[np.float64]
#: vertex, edge, face and triangle indices
Indices = npt.NDArray[np.int64]
#: what contains() and covers() return
Bools = npt.NDArray[np.bool_]

class UniformStep(TypedDict):
    """Eq. (4) of the uniform query: the slab index from y (zeros for other methods)."""

    y_min: float
    height: float
    value: float
    slabs: int

class PolarStep(TypedDict):
    """The polar index: direction from the centre, ratio, octant slab (zeros for other methods)."""

    direction: tuple[float, float]
    ratio: float
    steep: bool
    slab: int
    slabs: int
    base: int
    step: int

class _TraceCommon(TypedDict):
    """The fields every trace has: the method, the answer, the cell's radius decision."""

    method: str
    result: int
    location: Location      # the same value locate() gives, an IntEnum
    location_name: str      # its name in words: "inside", "boundary" or "outside"
    crowded: bool
    at_centre: bool
    by_radius: bool
    distance: float
    inner_radius: float
    outer_radius: float

class Trace2D(_TraceCommon):
    """What one 2D query did (trace()): the cell, each test with its sign, the result."""

    outside_box: bool
    cell: int
    octant: int
    apex: tuple[float, float]
    rays: list[tuple[int, int]]                # (vertex, sign)
    edges: list[tuple[int, int]]               # (edge, sign)
    radius_filter: bool
    probes: list[tuple[int, float, bool]]      # the slab search: (rank, y, above)
    uniform: UniformStep
    polar: PolarStep

class Stats2D(TypedDict):
    """The size and shape of a 2D subdivision (stats())."""

    edges: int
    cells: int
    entries: int
    max_per_cell: int
    mean_per_cell: float
    crowded_cells: int
    bytes: int
    bytes_per_edge: float
    build_seconds: float
    histogram: list[int]

class Cell2D(TypedDict):
    """One 2D cell (cells()): its outline to draw and the edges it lists."""

    index: int
    octant: int
    outline: Floats  # (k, 2)
    dir_lo: tuple[float, float]
    dir_hi: tuple[float, float]
    hit_lo: tuple[float, float]
    hit_hi: tuple[float, float]
    y0: float
    y1: float
    edges: Indices

class Trace3D(_TraceCommon):
    """What one 3D query did (trace()): the cube cell or the walk, each test, the result."""

    non_finite: bool
    fallback: bool
    centre: tuple[float, float, float] | None
    cube_face: int
    level: int
    cell_i: int
    cell_j: int
    s: float
    t: float
    path: Indices
    steps: list[tuple[int, int, int]]  # (face, edge, sign)
    faces: list[tuple[int, int]]       # (face, sign)
    zone_steps: list[tuple[int, int, int, int]]  # (zone edge, vertex a, vertex b, sign)
    sector_steps: list[tuple[int, int, int]]  # (fan place, key vertex, sign)
    radius_filter: bool
    direction: tuple[float, float, float]
    cells_per_side: int

class Stats3D(TypedDict):
    """The size and shape of a 3D subdivision (stats())."""

    faces: int      # plane faces: coplanar neighbouring triangles merged
    triangles: int
    vertices: int
    cells: int
    nodes: int
    entries: int
    max_per_cell: int
    mean_per_cell: float
    crowded_cells: int
    zone_cells: int
    sector_cells: int
    resolution: int
    max_level: int
    centred: bool
    bytes: int
    bytes_per_face: float
    build_seconds: float
    histogram: list[int]

class Cell3D(TypedDict):
    """One cube-map cell (cells()): its square on the cube and the faces it lists."""

    index: int
    cube_face: int
    level: int
    i: int
    j: int
    s0: float
    s1: float
    t0: float
    t1: float
    apex: tuple[float, float, float]
    corners: Floats  # (4, 3)
    faces: Indices
