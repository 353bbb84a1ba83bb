"""convexloc: exact O(1) point location in convex polygons and polyhedra.

Build a shape once, then a locator over it; locate any number of points at once:

    >>> import numpy as np, convexloc
    >>> square = convexloc.Polygon([[0, 0], [1, 0], [1, 1], [0, 1]])
    >>> polar = convexloc.PolarLocator(square)
    >>> polar.locate(np.array([[0.5, 0.5], [0.5, 1.0], [2.0, 0.0]]))
    array([0, 1, 2], dtype=int8)

The codes are INSIDE (0), BOUNDARY (1) and OUTSIDE (2), exact for the doubles given: a point
is on the boundary only when it lies exactly on it. One call does both steps:
contains(polygon_vertices, points) and hull_contains(cloud, points).
"""

from ._core import (
    BOUNDARY,
    INSIDE,
    OUTSIDE,
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
    read_polygon,
    read_polyhedron,
    set_vector_batches,
    vector_batches,
)

#: the 2D locator classes by method name, in the paper's order
LOCATORS_2D = {
    cls.method: cls
    for cls in (HalfplaneLocator, WedgeLocator, SlabLocator, UniformLocator, PolarLocator)
}
#: the 3D locator classes by method name
LOCATORS_3D = {cls.method: cls for cls in (HalfspaceLocator, WalkLocator, CubemapLocator)}

#: a code's name: NAMES[code] is "inside", "boundary" or "outside"
NAMES = ("inside", "boundary", "outside")

from .chunks import iter_locate, locate_chunks  # noqa: E402  (it uses the tables above)

__all__ = [
    "BOUNDARY", "INSIDE", "OUTSIDE", "NAMES", "LOCATORS_2D", "LOCATORS_3D",
    "Error", "FileError", "GeometryError", "ParseError", "UsageError",
    "Polygon", "Polyhedron", "read_polygon", "read_polyhedron",
    "HalfplaneLocator", "WedgeLocator", "SlabLocator", "UniformLocator", "PolarLocator",
    "HalfspaceLocator", "WalkLocator", "CubemapLocator",
    "iter_locate", "locate_chunks",
    "contains", "covers", "hull_contains", "hull_covers", "set_vector_batches", "vector_batches",
]
