"""convexloc over Dask: classify points that do not fit one machine, chunk by chunk.

    >>> import dask.array as da, convexloc, convexloc.dask
    >>> square = convexloc.Polygon([[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> points = da.from_array([[0.5, 0.5], [1.0, 0.5], [2.0, 2.0]], chunks=(2, 2))
    >>> convexloc.dask.locate(points, square).compute()
    array([0, 1, 2], dtype=int8)

The shape (or locator) travels to the workers once, as one task of the graph that every
chunk depends on; each worker process builds the locator once, on its first chunk, and keeps
it in a small per-process cache keyed by the pickled shape's SHA-256, so a graph of 10^5
chunks builds it once per process, not 10^5 times. A chunk lost with a worker is recomputed
elsewhere, like any Dask task: the answer is complete and exact either way.
"""

from __future__ import annotations

import hashlib
import pickle
import threading
from collections import OrderedDict
from collections.abc import Callable, Sequence
from typing import Any, Union, cast

import numpy as np
import numpy.typing as npt
from dask.array import core as _array
from dask.array.core import Array
from dask.delayed import delayed

# dask.array's functions carry no annotations: these names give them their types here
asarray: Callable[..., Array] = _array.asarray
map_blocks: Callable[..., Array] = _array.map_blocks

from . import LOCATORS_2D, LOCATORS_3D, Polygon, Polyhedron
from .chunks import geo_polygon

__all__ = ["locate", "locate_dataframe", "build_counts"]

#: the method used when none is given: the O(1) locator of each dimension
DEFAULT_METHOD = {2: "polar", 3: "cubemap"}

#: locators kept per worker process (the most recently used)
CACHE_SIZE = 4


class LocatorSpec:
    """What a worker needs to build the locator: the pickled shape, method and resolution,
    with the SHA-256 of those bytes as the key of the per-process cache."""

    __slots__ = ("payload", "key", "dims")

    def __init__(self, payload: bytes, dims: int) -> None:
        self.payload = payload
        self.key = hashlib.sha256(payload).hexdigest()
        self.dims = dims

    def __reduce__(self) -> tuple[Any, ...]:
        return (LocatorSpec, (self.payload, self.dims))

    def __repr__(self) -> str:
        return f"<convexloc.dask.LocatorSpec {self.key[:12]} ({len(self.payload)} bytes)>"


def _table(dims: int) -> dict[str, Any]:
    """The locator classes of a dimension by method name."""
    return dict(LOCATORS_2D) if dims == 2 else dict(LOCATORS_3D)


def spec_of(shape_or_locator: Any, method: str | None = None) -> LocatorSpec:
    """The spec of a Polygon or Polyhedron with a method name (None: polar or cubemap), or of
    a locator (then method must be None or the locator's own). A Shapely polygon or a GeoJSON
    mapping is made a Polygon first."""
    shape_or_locator = geo_polygon(shape_or_locator)
    if isinstance(shape_or_locator, (Polygon, Polyhedron)):
        dims = 2 if isinstance(shape_or_locator, Polygon) else 3
        table = _table(dims)
        name = DEFAULT_METHOD[dims] if method is None else method
        if name not in table:
            raise ValueError(f"method must be one of {', '.join(table)} for a "
                             f"{type(shape_or_locator).__name__}, got {name!r}")
        return LocatorSpec(pickle.dumps(("shape", name, shape_or_locator), protocol=5), dims)
    cls = type(shape_or_locator)
    for dims in (2, 3):
        if _table(dims).get(getattr(cls, "method", "")) is cls:
            if method is not None and method != cls.method:
                raise ValueError(f"method={method!r} given with a {cls.__name__}: pass the "
                                 f"shape to choose a method, or method=None")
            return LocatorSpec(pickle.dumps(("locator", cls.method, shape_or_locator),
                                            protocol=5), dims)
    raise TypeError("shape_or_locator must be a convexloc.Polygon, Polyhedron or locator, got "
                    f"{cls.__name__}")


# === The per-process cache (one per worker process; threads share it)

_lock = threading.Lock()
_cache: "OrderedDict[str, Any]" = OrderedDict()
_builds: dict[str, int] = {}
_chunks: dict[str, int] = {}


def locator_of(spec: LocatorSpec) -> Any:
    """The locator `spec` describes, built on this process's first call for it."""
    with _lock:
        locator = _cache.get(spec.key)
        if locator is None:
            kind, name, obj = pickle.loads(spec.payload)
            if kind == "shape":
                locator = _table(spec.dims)[name](obj)
            else:
                locator = obj  # unpickling a locator rebuilt it
            _builds[spec.key] = _builds.get(spec.key, 0) + 1
            _cache[spec.key] = locator
            while len(_cache) > CACHE_SIZE:
                _cache.popitem(last=False)
        _cache.move_to_end(spec.key)
        _chunks[spec.key] = _chunks.get(spec.key, 0) + 1
        return locator


def build_counts() -> dict[str, tuple[int, int]]:
    """In this process: for each spec key, (locators built, chunks located). A diagnostic:
    read it on the workers with client.run(convexloc.dask.build_counts)."""
    with _lock:
        return {key: (_builds[key], _chunks.get(key, 0)) for key in _builds}


# === The chunk functions (run on the workers)


Codes = npt.NDArray[np.int8]


def _locate_rows(block: npt.NDArray[np.float64], spec: LocatorSpec, workers: int) -> Codes:
    codes: Codes = locator_of(spec).locate(block, workers=workers)
    return codes


def _locate_columns(*blocks_and_spec: Any, workers: int) -> Codes:
    *blocks, spec = blocks_and_spec
    locator = locator_of(spec)
    codes: Codes
    if spec.dims == 2:
        codes = locator.locate_xy(*blocks, workers=workers)
    else:
        codes = locator.locate_xyz(*blocks, workers=workers)
    return codes


def _locate_frame(frame: Any, columns: Sequence[str], spec: LocatorSpec, workers: int) -> Any:
    # Debian's pandas ships no type information
    import pandas  # type: ignore[import]

    values = [frame[c].to_numpy() for c in columns]
    codes = _locate_columns(*values, spec, workers=workers)
    return pandas.Series(codes, index=frame.index, name="location", dtype=np.int8)


# === The API

PointsArg = Union[Array, npt.NDArray[Any], Sequence[Union[Array, npt.NDArray[Any]]]]


def locate(points: PointsArg, shape_or_locator: Any, method: str | None = None, *,
           workers: int = 1) -> Array:
    """Locates Dask points against a shape (or a locator): a lazy int8 Dask array of
    INSIDE (0), BOUNDARY (1), OUTSIDE (2), exact.

    points: an (M, 2) or (M, 3) Dask array (chunked along M; the coordinate axis is made one
    chunk), or a tuple (x, y) / (x, y, z) of Dask arrays that broadcast together (the answer
    has their broadcast shape and chunks). NumPy arrays are wrapped with dask.array.asarray.
    method: a key of LOCATORS_2D / LOCATORS_3D (None: polar in 2D, cubemap in 3D); with a
    locator, its own method and resolution are used. workers: threads per chunk (1 leaves
    the parallelism to Dask)."""
    spec = spec_of(shape_or_locator, method)
    shared = delayed(spec, pure=True)  # one task every chunk depends on
    if isinstance(points, (tuple, list)):
        if len(points) != spec.dims:
            raise ValueError(f"points: {len(points)} coordinate arrays given, the shape needs "
                             f"{spec.dims}")
        columns = [asarray(c) for c in points]
        return map_blocks(_locate_columns, *columns, shared, workers=workers,
                             dtype=np.int8, meta=np.empty((0,) * max(c.ndim for c in columns),
                                                          dtype=np.int8))
    rows = asarray(points)
    if rows.ndim != 2 or rows.shape[1] != spec.dims:
        raise ValueError(f"points must be an (M, {spec.dims}) array, got shape {rows.shape}")
    rows = cast(Array, getattr(rows, "rechunk")({1: -1}))  # (an untyped method)
    return map_blocks(_locate_rows, rows, shared, workers, drop_axis=1, dtype=np.int8,
                         meta=np.empty((0,), dtype=np.int8))


def locate_dataframe(frame: Any, shape_or_locator: Any, method: str | None = None, *,
                     columns: Sequence[str] | None = None, workers: int = 1) -> Any:
    """Locates the rows of a Dask DataFrame whose columns x, y (and z for a polyhedron) are
    coordinates: a lazy int8 Dask Series named "location", partitioned as the frame.
    columns: other column names, in x, y(, z) order."""
    spec = spec_of(shape_or_locator, method)
    names = list(columns) if columns is not None else ["x", "y", "z"][: spec.dims]
    if len(names) != spec.dims:
        raise ValueError(f"columns: {len(names)} names given, the shape needs {spec.dims}")
    missing = [c for c in names if c not in frame.columns]
    if missing:
        raise ValueError(f"columns {missing} are not in the frame (it has {list(frame.columns)})")
    shared = delayed(spec, pure=True)
    return frame.map_partitions(_locate_frame, names, shared, workers,
                                meta=("location", np.int8))
