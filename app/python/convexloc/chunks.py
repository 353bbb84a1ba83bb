"""Locating more points than fit in memory, one chunk at a time, without Dask.

A source is a memory-mapped (or any) array, a ``.npy`` file (opened memory-mapped), a text
points file (one point per line, "x y" or "x y z", blank lines and "#" comments skipped), or
any iterable of (k, dims) arrays. Only one chunk of points is in memory at a time.
"""

from __future__ import annotations

import itertools
import os
import warnings
from collections.abc import Callable, Iterable, Iterator, Mapping
from typing import Any, Optional, Union

import numpy as np
import numpy.typing as npt

from . import LOCATORS_2D, LOCATORS_3D, ParseError, Polygon, Polyhedron

__all__ = ["iter_locate", "locate_chunks"]

#: points per chunk when none is given: 2^20 points are 16 or 24 MiB of doubles
DEFAULT_CHUNK = 1 << 20

Progress = Callable[[int, Optional[int]], Any]
Source = Union[str, "os.PathLike[str]", npt.NDArray[Any], Iterable[Any]]
Codes = npt.NDArray[np.int8]
Floats = npt.NDArray[np.float64]


def geo_polygon(value: Any) -> Any:
    """`value` as a Polygon when it is a geometry (an object with __geo_interface__, such as a
    Shapely polygon, or a GeoJSON mapping); anything else as it is."""
    if isinstance(value, (Polygon, Polyhedron)):
        return value
    if hasattr(value, "__geo_interface__") or isinstance(value, Mapping):
        return Polygon(value)
    return value


def _locator(shape_or_locator: Any) -> Any:
    """A locator as given, or the O(1) one of a shape (polar, cubemap)."""
    shape_or_locator = geo_polygon(shape_or_locator)
    if isinstance(shape_or_locator, Polygon):
        return LOCATORS_2D["polar"](shape_or_locator)
    if isinstance(shape_or_locator, Polyhedron):
        return LOCATORS_3D["cubemap"](shape_or_locator)
    if type(shape_or_locator) in LOCATORS_2D.values() or type(shape_or_locator) in LOCATORS_3D.values():
        return shape_or_locator
    raise TypeError("locator must be a convexloc locator, Polygon or Polyhedron, got "
                    f"{type(shape_or_locator).__name__}")


def _parse_error(path: str, line: int, problem: str) -> ParseError:
    error = ParseError(f"{path}:{line}: {problem}")
    error.path, error.line, error.problem = path, line, problem
    return error


def _text_rows(path: str, lines: list[str], first: int, dims: int) -> Floats:
    """The points of `lines` (line `first` of the file onwards): numpy's parser, and where it
    fails, a line by line pass that names the line."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a chunk of comments only: no data, no warning
            rows = np.loadtxt(lines, dtype=np.float64, comments="#", ndmin=2)
        if rows.size == 0:
            return np.empty((0, dims))
        if rows.shape[1] == dims:
            return rows
    except ValueError:
        pass
    return _text_rows_checked(path, lines, first, dims)


def _text_rows_checked(path: str, lines: list[str], first: int, dims: int) -> Floats:
    rows = []
    for k, text in enumerate(lines):
        fields = text.split("#", 1)[0].split()
        if not fields:
            continue
        if len(fields) != dims:
            raise _parse_error(path, first + k, f"expected {dims} numbers, got {len(fields)}")
        try:
            rows.append([float(f) for f in fields])
        except ValueError:
            bad = next(f for f in fields if not _is_float(f))
            raise _parse_error(path, first + k, f"not a number: {bad!r}") from None
    return np.array(rows, dtype=np.float64).reshape(-1, dims)


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _text_chunks(path: str, chunk: int, dims: int) -> Iterator[Floats]:
    with open(path, encoding="utf-8") as f:
        first = 1
        while True:
            lines = list(itertools.islice(f, chunk))
            if not lines:
                return
            yield _text_rows(path, lines, first, dims)
            first += len(lines)


def _array_chunks(array: Any, chunk: int) -> Iterator[Any]:
    for start in range(0, len(array), chunk):
        yield array[start:start + chunk]


def _chunks(source: Source, chunk: int, dims: int) -> tuple[Iterator[Any], Optional[int]]:
    """The source's chunks, and its point count when known."""
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        if path.endswith(".npy"):
            array = np.load(path, mmap_mode="r")
            return _array_chunks(array, chunk), len(array)
        return _text_chunks(path, chunk, dims), None
    if isinstance(source, np.ndarray):
        return _array_chunks(source, chunk), len(source)
    return iter(source), None


def iter_locate(source: Source, locator: Any, *, chunk: int = DEFAULT_CHUNK,
                progress: Optional[Progress] = None, workers: int = 1) -> Iterator[Codes]:
    """Yields the int8 codes of each chunk of `source` in turn (see the module's docstring),
    located by `locator` (a locator, or a Polygon / Polyhedron for its O(1) locator; a Shapely
    polygon or a GeoJSON mapping is made a Polygon).
    progress(done, total) is called after each chunk: points located so far, and the total
    when the source knows it (an array, a .npy file), else None."""
    if chunk < 1:
        raise ValueError(f"chunk must be >= 1, got {chunk}")
    located = _locator(locator)
    dims = 2 if type(located) in LOCATORS_2D.values() else 3
    chunks, total = _chunks(source, chunk, dims)
    done = 0
    for points in chunks:
        codes = located.locate(points, workers=workers)
        done += len(codes)
        if progress is not None:
            progress(done, total)
        yield codes


def locate_chunks(source: Source, locator: Any, *, chunk: int = DEFAULT_CHUNK,
                  out: Optional[Codes] = None, progress: Optional[Progress] = None,
                  workers: int = 1) -> Codes:
    """The int8 codes of every point of `source`, located chunk by chunk (see iter_locate):
    written into `out` when given (an int8 array of the points' count, e.g. a np.memmap, so
    that nothing grows with the input), else returned as a new array."""
    parts = iter_locate(source, locator, chunk=chunk, progress=progress, workers=workers)
    if out is None:
        return np.concatenate([np.empty(0, dtype=np.int8), *parts])
    if out.dtype != np.int8 or out.ndim != 1:
        raise ValueError(f"out must be a 1-D int8 array, got {out.dtype} of shape {out.shape}")
    start = 0
    for codes in parts:
        if start + len(codes) > len(out):
            raise ValueError(f"out has {len(out)} elements, the source has more points")
        out[start:start + len(codes)] = codes
        start += len(codes)
    if start != len(out):
        raise ValueError(f"out has {len(out)} elements, the source has {start} points")
    return out
