"""Type stubs for convexloc: exact O(1) point location in convex polygons and polyhedra."""

import enum
import os
from typing import (Any, Callable, ClassVar, Final, Generic, Iterable, Iterator, Sequence,
                    TypedDict, TypeVar, Union)

import numpy as np
import numpy.typing as npt

from . import chunks as chunks

__version__: str

# === Codes

class Location(enum.IntEnum):
    """Where a point lies: the int8 codes every locate() returns, by name."""
    INSIDE = 0
    BOUNDARY = 1
    OUTSIDE = 2

INSIDE: Final = Location.INSIDE
BOUNDARY: Final = Location.BOUNDARY
OUTSIDE: Final = Location.OUTSIDE
NAMES: tuple[str, str, str]

ArrayLike = npt.ArrayLike
PathLike = Union[str, os.PathLike[str]]
Codes = npt.NDArray[np.int8]
Floats = npt.NDArray[np.float64]
Indices = npt.NDArray[np.int64]
Bools = npt.NDArray[np.bool_]

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
    collinear vertices). Immutable, picklable, compared and hashed by value."""
    def __init__(self, vertices: ArrayLike | Any) -> None: ...
    @staticmethod
    def hull(points: ArrayLike) -> Polygon: ...
    @property
    def vertices(self) -> Floats: ...
    def __len__(self) -> int: ...
    @property
    def bounds(self) -> tuple[tuple[float, float], tuple[float, float]]: ...
    @property
    def area(self) -> float: ...
    @property
    def source_index(self) -> Indices: ...
    @property
    def dropped_count(self) -> int: ...
    @property
    def was_clockwise(self) -> bool: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __hash__(self, /) -> int: ...

class Polyhedron:
    """A closed convex polyhedron, validated once, as triangles counter-clockwise from
    outside. Immutable, picklable, compared and hashed by value."""
    def __init__(self, vertices: ArrayLike, faces: ArrayLike | Sequence[Sequence[int]]) -> None: ...
    @staticmethod
    def hull(points: ArrayLike) -> Polyhedron: ...
    @property
    def vertices(self) -> Floats: ...
    @property
    def triangles(self) -> Indices: ...
    @property
    def neighbours(self) -> Indices: ...
    @property
    def face_count(self) -> int: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def centre(self) -> tuple[float, float, float] | None: ...
    @property
    def bounds(self) -> tuple[tuple[float, float, float], tuple[float, float, float]]: ...
    @property
    def volume(self) -> float: ...
    @property
    def area(self) -> float: ...
    @property
    def source_face(self) -> Indices: ...
    @property
    def source_vertex(self) -> Indices: ...
    @property
    def was_inverted(self) -> bool: ...
    def __eq__(self, other: object, /) -> bool: ...
    def __hash__(self, /) -> int: ...

def read_polygon(path: PathLike) -> Polygon: ...
def read_polyhedron(path: PathLike) -> Polyhedron: ...

# === Introspection values

class UniformStep(TypedDict):
    y_min: float
    height: float
    value: float
    slabs: int

class PolarStep(TypedDict):
    direction: tuple[float, float]
    ratio: float
    steep: bool
    slab: int
    slabs: int
    base: int
    step: int

class Trace2D(TypedDict):
    method: str
    result: int
    location: str
    crowded: bool
    at_centre: bool
    by_radius: bool
    distance: float
    inner_radius: float
    outer_radius: float
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
    crowded: bool
    at_centre: bool
    by_radius: bool
    distance: float
    inner_radius: float
    outer_radius: float
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
    radius_filter: bool
    direction: tuple[float, float, float]
    cells_per_side: int

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

_Shape = TypeVar("_Shape", Polygon, Polyhedron)
_Trace = TypeVar("_Trace", Trace2D, Trace3D)
_Stats = TypeVar("_Stats", Stats2D, Stats3D)
_Cell = TypeVar("_Cell", Cell2D, Cell3D)

class _Locator(Generic[_Shape, _Trace, _Stats, _Cell]):
    """What every locator class has (not a runtime class)."""
    method: ClassVar[str]
    @property
    def shape(self) -> _Shape: ...
    def locate(self, points: ArrayLike, *, workers: int = -1, threads: int | None = None) -> Codes: ...
    def trace(self, point: ArrayLike, *, radii: bool = True) -> _Trace: ...
    def stats(self) -> _Stats: ...
    def cells(self) -> list[_Cell]: ...

class _Locator2D(_Locator[Polygon, Trace2D, Stats2D, Cell2D]):
    def __init__(self, polygon: Polygon, resolution: int = 0) -> None: ...
    def locate_xy(self, x: ArrayLike, y: ArrayLike, *, workers: int = -1,
                  threads: int | None = None) -> Codes: ...

class HalfplaneLocator(_Locator2D):
    def __init__(self, polygon: Polygon) -> None: ...

class WedgeLocator(_Locator2D):
    def __init__(self, polygon: Polygon) -> None: ...

class SlabLocator(_Locator2D):
    def __init__(self, polygon: Polygon) -> None: ...

class UniformLocator(_Locator2D):
    def __init__(self, polygon: Polygon, resolution: int = 0) -> None: ...
    @property
    def slab_count(self) -> int: ...

class PolarLocator(_Locator2D):
    def __init__(self, polygon: Polygon, resolution: int = 0) -> None: ...
    @property
    def centre(self) -> tuple[float, float]: ...
    @property
    def slabs_per_octant(self) -> int: ...
    @property
    def box(self) -> tuple[tuple[float, float], tuple[float, float]]: ...

class _Locator3D(_Locator[Polyhedron, Trace3D, Stats3D, Cell3D]):
    def __init__(self, polyhedron: Polyhedron, resolution: int = 0) -> None: ...
    def locate_xyz(self, x: ArrayLike, y: ArrayLike, z: ArrayLike, *, workers: int = -1,
                   threads: int | None = None) -> Codes: ...

class HalfspaceLocator(_Locator3D):
    def __init__(self, polyhedron: Polyhedron) -> None: ...

class WalkLocator(_Locator3D):
    def __init__(self, polyhedron: Polyhedron) -> None: ...
    @property
    def centre(self) -> tuple[float, float, float] | None: ...

class CubemapLocator(_Locator3D):
    def __init__(self, polyhedron: Polyhedron, resolution: int = 0) -> None: ...
    @property
    def centre(self) -> tuple[float, float, float] | None: ...
    @property
    def resolution(self) -> int: ...
    @property
    def cube_half_size(self) -> float: ...

# the classes by method name: LOCATORS_2D["polar"](polygon) is a _Locator2D
LOCATORS_2D: dict[str, type[_Locator2D]]
LOCATORS_3D: dict[str, type[_Locator3D]]

# === One call

def contains(polygon: ArrayLike | Polygon, points: ArrayLike, *, workers: int = -1,
             threads: int | None = None, boundary: bool | None = None) -> Bools: ...
def covers(polygon: ArrayLike | Polygon, points: ArrayLike, *, workers: int = -1,
           threads: int | None = None) -> Bools: ...
def hull_contains(cloud: ArrayLike | Polyhedron, points: ArrayLike, *, workers: int = -1,
                  threads: int | None = None, boundary: bool | None = None) -> Bools: ...
def hull_covers(cloud: ArrayLike | Polyhedron, points: ArrayLike, *, workers: int = -1,
                threads: int | None = None) -> Bools: ...

# === Chunk by chunk

_Source = Union[PathLike, npt.NDArray[Any], Iterable[ArrayLike]]
_AnyLocator = Union[_Locator2D, _Locator3D, Polygon, Polyhedron]

def iter_locate(source: _Source, locator: _AnyLocator, *, chunk: int = ...,
                progress: Callable[[int, int | None], object] | None = None,
                workers: int = -1) -> Iterator[Codes]: ...
def locate_chunks(source: _Source, locator: _AnyLocator, *, chunk: int = ...,
                  out: Codes | None = None,
                  progress: Callable[[int, int | None], object] | None = None,
                  workers: int = -1) -> Codes: ...

def set_vector_batches(enabled: bool) -> None: ...
def vector_batches() -> bool: ...

__all__: list[str]
