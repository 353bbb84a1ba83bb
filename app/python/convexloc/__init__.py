"""convexloc: exact O(1) point location in convex polygons and polyhedra.

Build a shape once, then a locator over it; locate any number of points at once:

    >>> import numpy as np, convexloc
    >>> square = convexloc.Polygon([[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> polar = convexloc.PolarLocator(square)
    >>> polar.locate(np.array([[0.5, 0.5], [0.5, 1.0], [2.0, 0.0]]))
    array([0, 1, 2], dtype=int8)

The codes are Location.INSIDE (0), BOUNDARY (1) and OUTSIDE (2), exact for the doubles
given: a point is on the boundary only when it lies exactly on it. One call does both steps:
contains(polygon, points) (the interior, as Shapely names it), covers(polygon, points) (the
boundary counts), and hull_contains / hull_covers(cloud, points) for the hull of a 3D cloud.
"""

import enum as _enum
import functools as _functools
import inspect as _inspect

from . import _core
from ._core import (
    CubemapLocator,
    Error,
    FileError,
    GeometryError,
    HalfplaneLocator,
    HalfspaceLocator,
    ParseError,
    PolarLocator,
    Polygon,
    Polyhedron,
    SlabLocator,
    UniformLocator,
    UsageError,
    WalkLocator,
    WedgeLocator,
    __version__,
    contains,
    covers,
    hull_contains,
    hull_covers,
    set_vector_batches,
    vector_batches,
)


class Location(_enum.IntEnum):
    """Where a point lies: the int8 codes every locate() returns, by name
    (Location(codes[i]) names one; they compare equal to the plain ints)."""

    INSIDE = _core.INSIDE
    BOUNDARY = _core.BOUNDARY
    OUTSIDE = _core.OUTSIDE


INSIDE = Location.INSIDE
BOUNDARY = Location.BOUNDARY
OUTSIDE = Location.OUTSIDE

#: a code's name: NAMES[code] is "inside", "boundary" or "outside"
NAMES = ("inside", "boundary", "outside")

#: the 2D locator classes by method name, in the paper's order
LOCATORS_2D = {
    cls.method: cls
    for cls in (HalfplaneLocator, WedgeLocator, SlabLocator, UniformLocator, PolarLocator)
}
#: the 3D locator classes by method name
LOCATORS_3D = {cls.method: cls for cls in (HalfspaceLocator, WalkLocator, CubemapLocator)}


def _signed(function):
    """`function` (a pybind11 builtin with a text signature) behind a Python function of this
    module, with the same signature."""

    @_functools.wraps(function)
    def wrapper(*args, **kwargs):
        return function(*args, **kwargs)

    wrapper.__signature__ = _inspect.signature(function)
    wrapper.__module__ = __name__
    return wrapper


read_polygon = _signed(_core.read_polygon)
read_polyhedron = _signed(_core.read_polyhedron)

from . import types  # noqa: E402
from .render import figure, figure_svg, plot, svg  # noqa: E402  (matplotlib: only when called)
from .chunks import iter_locate, locate_chunks  # noqa: E402  (it uses the tables above)
from .types import (  # noqa: E402
    Cell2D,
    Cell3D,
    GeoInterface,
    PolarStep,
    PolygonLike,
    Stats2D,
    Stats3D,
    Trace2D,
    Trace3D,
    UniformStep,
)


#: the most edges (triangles) a notebook draws as SVG; a larger shape shows its repr
SVG_LIMIT = 20_000


def _repr_svg_(self):
    """The notebook's picture of a shape or locator, convexloc.svg(self); None (the repr is
    shown) for a shape of more than SVG_LIMIT edges or triangles."""
    shape = self if isinstance(self, (Polygon, Polyhedron)) else self.shape
    size = len(shape) if isinstance(shape, Polygon) else shape.face_count
    return svg(self) if size <= SVG_LIMIT else None


for _cls in (Polygon, Polyhedron, *LOCATORS_2D.values(), *LOCATORS_3D.values()):
    _cls._repr_svg_ = _repr_svg_
del _cls

__all__ = [
    "Location", "BOUNDARY", "INSIDE", "OUTSIDE", "NAMES", "LOCATORS_2D", "LOCATORS_3D",
    "Error", "FileError", "GeometryError", "ParseError", "UsageError",
    "Polygon", "Polyhedron", "read_polygon", "read_polyhedron",
    "HalfplaneLocator", "WedgeLocator", "SlabLocator", "UniformLocator", "PolarLocator",
    "HalfspaceLocator", "WalkLocator", "CubemapLocator",
    "iter_locate", "locate_chunks",
    "Trace2D", "Stats2D", "Cell2D", "Trace3D", "Stats3D", "Cell3D", "UniformStep", "PolarStep",
    "contains", "covers", "hull_contains", "hull_covers", "set_vector_batches", "vector_batches",
    "plot", "figure", "svg", "figure_svg",
]
