"""Type stubs for convexloc: exact O(1) point location in convex polygons and polyhedra."""

import os
from typing import (Any, Callable, ClassVar, Final, Generic, Iterable, Iterator, Sequence,
                    TypedDict, TypeVar, Union)

import numpy as np
import numpy.typing as npt

__version__: str

# === Codes

INSIDE: int
BOUNDARY: int
OUTSIDE: int
NAMES: tuple[str, str, str]

ArrayLike = npt.ArrayLike
PathLike = Union[str, os.PathLike[str]]
Codes = npt.NDArray[np.int8]
Floats = npt.NDArray[np.float64]
Indices = npt.NDArray[np.int64]

# === Errors

class Error(ValueError):
    """Base of every convexloc error; str() is 'FILE:LINE: problem' for a file."""
    path: str | None
    line: int
    problem: str

class ParseError(Error): ...
class GeometryError(Error): ...
class UsageError(Error): ...
class FileError(Error, OSError): ...

# === Shapes

class Polygon:
    """A strictly convex polygon, validated once (counter-clockwise, no repeated or
    collinear vertices)."""
    def __init__(self, vertices: ArrayLike) -> None: ...
    vertices: Final[Floats]
    def __len__(self) -> int: ...
    bounds: Final[tuple[tuple[float, float], tuple[float, float]]]
    area: Final[float]
    source_index: Final[Indices]
    dropped_count: Final[int]
    was_clockwise: Final[bool]

class Polyhedron:
    """A closed convex polyhedron, validated once, as triangles counter-clockwise from
    outside."""
    def __init__(self, vertices: ArrayLike, faces: ArrayLike | Sequence[Sequence[int]]) -> None: ...
    @staticmethod
    def hull(points: ArrayLike) -> Polyhedron: ...
    vertices: Final[Floats]
    triangles: Final[Indices]
    neighbours: Final[Indices]
    face_count: Final[int]
    vertex_count: Final[int]
    centre: Final[tuple[float, float, float] | None]
    bounds: Final[tuple[tuple[float, float, float], tuple[float, float, float]]]
    volume: Final[float]
    area: Final[float]
    source_face: Final[Indices]
    source_vertex: Final[Indices]
    was_inverted: Final[bool]

def read_polygon(path: PathLike) -> Polygon: ...
def read_polyhedron(path: PathLike) -> Polyhedron: ...

# === Introspection values

class Trace2D(TypedDict):
    method: str
    result: int
    location: str
    outside_box: bool
    cell: int
    octant: int
    crowded: bool
    at_centre: bool
    by_radius: bool
    distance: float
    inner_radius: float
    outer_radius: float
    apex: tuple[float, float]
    rays: list[tuple[int, int]]   # (vertex, sign)
    edges: list[tuple[int, int]]  # (edge, sign)

class Stats2D(TypedDict):
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

class Trace3D(TypedDict):
    method: str
    result: int
    location: str
    non_finite: bool
    at_centre: bool
    fallback: bool
    crowded: bool
    by_radius: bool
    distance: float
    inner_radius: float
    outer_radius: float
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

class Stats3D(TypedDict):
    faces: int
    vertices: int
    cells: int
    nodes: int
    entries: int
    max_per_cell: int
    mean_per_cell: float
    crowded_cells: int
    resolution: int
    max_level: int
    centred: bool
    bytes: int
    bytes_per_face: float
    build_seconds: float
    histogram: list[int]

class Cell3D(TypedDict):
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

# === Locators

_Trace = TypeVar("_Trace", Trace2D, Trace3D)
_Stats = TypeVar("_Stats", Stats2D, Stats3D)
_Cell = TypeVar("_Cell", Cell2D, Cell3D)

class _Locator(Generic[_Trace, _Stats, _Cell]):
    """What every locator class has."""
    method: ClassVar[str]
    @property
    def shape(self) -> Polygon | Polyhedron: ...
    def locate(self, points: ArrayLike, *, workers: int = -1, threads: int | None = None) -> Codes: ...
    def trace(self, point: ArrayLike, *, radii: bool = True) -> _Trace: ...
    def stats(self) -> _Stats: ...
    def cells(self) -> list[_Cell]: ...

class _Locator2D(_Locator[Trace2D, Stats2D, Cell2D]):
    def locate_xy(self, x: ArrayLike, y: ArrayLike, *, threads: int = 0) -> Codes: ...

class HalfplaneLocator(_Locator2D):
    def __init__(self, polygon: Polygon) -> None: ...

class WedgeLocator(_Locator2D):
    def __init__(self, polygon: Polygon) -> None: ...

class SlabLocator(_Locator2D):
    def __init__(self, polygon: Polygon) -> None: ...

class UniformLocator(_Locator2D):
    def __init__(self, polygon: Polygon, resolution: int = 0) -> None: ...
    slab_count: Final[int]

class PolarLocator(_Locator2D):
    def __init__(self, polygon: Polygon, resolution: int = 0) -> None: ...
    centre: Final[tuple[float, float]]
    slabs_per_octant: Final[int]
    box: Final[tuple[tuple[float, float], tuple[float, float]]]

class _Locator3D(_Locator[Trace3D, Stats3D, Cell3D]):
    def locate_xyz(self, x: ArrayLike, y: ArrayLike, z: ArrayLike, *, threads: int = 0) -> Codes: ...

class HalfspaceLocator(_Locator3D):
    def __init__(self, polyhedron: Polyhedron) -> None: ...

class WalkLocator(_Locator3D):
    def __init__(self, polyhedron: Polyhedron) -> None: ...
    centre: Final[tuple[float, float, float] | None]

class CubemapLocator(_Locator3D):
    def __init__(self, polyhedron: Polyhedron, resolution: int = 0) -> None: ...
    centre: Final[tuple[float, float, float] | None]
    resolution: Final[int]
    cube_half_size: Final[float]

LOCATORS_2D: dict[str, type[_Locator2D]]
LOCATORS_3D: dict[str, type[_Locator3D]]

# === One call

def contains(polygon: ArrayLike | Polygon, points: ArrayLike, *, workers: int = -1,
             threads: int | None = None, boundary: bool | None = None) -> npt.NDArray[np.bool_]: ...
def covers(polygon: ArrayLike | Polygon, points: ArrayLike, *, workers: int = -1,
           threads: int | None = None) -> npt.NDArray[np.bool_]: ...
def hull_contains(cloud: ArrayLike | Polyhedron, points: ArrayLike, *, workers: int = -1,
                  threads: int | None = None, boundary: bool | None = None) -> npt.NDArray[np.bool_]: ...
def hull_covers(cloud: ArrayLike | Polyhedron, points: ArrayLike, *, workers: int = -1,
                threads: int | None = None) -> npt.NDArray[np.bool_]: ...
# === Chunk by chunk

def iter_locate(source: PathLike | npt.NDArray[Any] | Iterable[ArrayLike],
                locator: _Locator[Any, Any, Any] | Polygon | Polyhedron, *, chunk: int = ...,
                progress: Callable[[int, int | None], object] | None = None,
                workers: int = -1) -> Iterator[Codes]: ...
def locate_chunks(source: PathLike | npt.NDArray[Any] | Iterable[ArrayLike],
                  locator: _Locator[Any, Any, Any] | Polygon | Polyhedron, *, chunk: int = ...,
                  out: Codes | None = None,
                  progress: Callable[[int, int | None], object] | None = None,
                  workers: int = -1) -> Codes: ...
def set_vector_batches(enabled: bool) -> None: ...
def vector_batches() -> bool: ...

__all__: list[str]
