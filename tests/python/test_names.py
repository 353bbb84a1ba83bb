"""Pythonic names: the Location enum, contains and covers as Shapely names them, workers=,
signatures inspect can read, polygons from __geo_interface__, the exact 2D hull, and errors
that name the user's own numbers."""

import inspect

import numpy as np
import pytest

import convexloc
from conftest import LATTICE_OCTAGON, on_edges_lattice, orient2d_exact


def test_location_enum_beside_the_int8_codes(square):
    L = convexloc.Location
    assert [m.name for m in L] == ["INSIDE", "BOUNDARY", "OUTSIDE"] and list(L) == [0, 1, 2]
    assert convexloc.INSIDE is L.INSIDE and convexloc.OUTSIDE == 2
    codes = convexloc.PolarLocator(square).locate([[0.5, 0.5], [1, 0.5], [3, 3]])
    assert codes.dtype == np.int8
    assert [L(c) for c in codes] == [L.INSIDE, L.BOUNDARY, L.OUTSIDE]
    assert (codes == L.BOUNDARY).tolist() == [False, True, False]
    assert [convexloc.NAMES[c] for c in codes] == [L(c).name.lower() for c in codes]


def test_contains_is_the_interior_and_covers_counts_the_boundary(square, cube):
    points = [[0.5, 0.5], [1, 0.5], [0, 0], [3, 3]]
    assert convexloc.contains(square, points).tolist() == [True, False, False, False]
    assert convexloc.covers(square, points).tolist() == [True, True, True, False]
    points3 = [[0, 0, 0], [1, 0, 0], [1, 1, 1], [2, 0, 0]]
    assert convexloc.hull_contains(cube, points3).tolist() == [True, False, False, False]
    assert convexloc.hull_covers(cube.vertices, points3).tolist() == [True, True, True, False]
    with pytest.warns(DeprecationWarning, match="contains is the interior only"):
        assert convexloc.contains(square, points, boundary=True).tolist() == [True, True, True, False]
    with pytest.raises(TypeError):
        convexloc.covers(square, points, boundary=False)


def public_callables():
    """Every public function, class and method of the module."""
    for name in convexloc.__all__:
        value = getattr(convexloc, name)
        if isinstance(value, type) and issubclass(value, (BaseException, int, dict)):
            continue  # exceptions, the Location enum and the TypedDicts: no signature to read
        if isinstance(value, type):
            yield name, value
            for member, attribute in vars(value).items():
                if not member.startswith("_") and callable(attribute):
                    yield f"{name}.{member}", getattr(value, member)
        elif callable(value):
            yield name, value


def test_every_public_callable_has_a_signature():
    found = dict(public_callables())
    assert len(found) > 30
    for name, value in found.items():
        inspect.signature(value)  # raises ValueError when it cannot tell


@pytest.mark.parametrize("target, expected", [
    (convexloc.PolarLocator, "(polygon, resolution=0)"),
    (convexloc.WedgeLocator, "(polygon)"),
    (convexloc.CubemapLocator, "(polyhedron, resolution=0)"),
    (convexloc.Polygon, "(vertices)"),
    (convexloc.Polyhedron, "(vertices, faces)"),
    (convexloc.Polygon.hull, "(points)"),
    (convexloc.PolarLocator.locate, "(self, points, *, workers=1, threads=None)"),
    (convexloc.CubemapLocator.locate_xyz, "(self, x, y, z, *, workers=1, threads=None)"),
    (convexloc.SlabLocator.trace, "(self, point, *, radii=True)"),
    (convexloc.covers, "(polygon, points, *, workers=1, threads=None)"),
    (convexloc.hull_contains, "(cloud, points, *, workers=1, threads=None, boundary=None)"),
    (convexloc.read_polygon, "(path)"),
    (convexloc.locate_chunks, "(source, locator, *, chunk=1048576, out=None, progress=None, workers=1)"),
])
def test_signatures_read_as_written(target, expected):
    assert _without_annotations(target) == expected


def _without_annotations(target):
    sig = inspect.signature(target)
    return str(sig.replace(parameters=[p.replace(annotation=inspect.Parameter.empty)
                                       for p in sig.parameters.values()],
                           return_annotation=inspect.Signature.empty))


def test_a_bound_method_drops_self(square):
    polar = convexloc.PolarLocator(square)
    assert list(inspect.signature(polar.locate_xy).parameters) == ["x", "y", "workers", "threads"]
    assert inspect.signature(polar.locate).bind([[0, 0]], workers=2)


class GeoSquare:
    """Any object with a Polygon __geo_interface__ (the ring closed, as GeoJSON writes it)."""

    @property
    def __geo_interface__(self):
        return {"type": "Polygon", "coordinates": (((0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0),
                                                    (0.0, 0.0)),)}


def test_polygon_from_geo_interface():
    polygon = convexloc.Polygon(GeoSquare())
    assert polygon == convexloc.Polygon([[0, 0], [2, 0], [2, 2], [0, 2]])
    assert polygon.dropped_count == 0  # the closing repeat is not an input vertex
    assert convexloc.Polygon(GeoSquare().__geo_interface__) == polygon  # the mapping itself
    holed = {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [0, 4], [0, 0]],
                                                [[1, 1], [2, 1], [1, 2], [1, 1]]]}
    with pytest.raises(convexloc.GeometryError, match="1 interior ring.*no holes"):
        convexloc.Polygon(holed)
    with pytest.raises(convexloc.GeometryError, match="a MultiPolygon of 0 parts"):
        convexloc.Polygon({"type": "MultiPolygon", "coordinates": []})
    with pytest.raises(TypeError, match="got type 'Point'"):
        convexloc.Polygon({"type": "Point", "coordinates": [0, 0]})
    with pytest.raises(convexloc.GeometryError, match="not convex"):
        convexloc.Polygon({"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [1, 1], [0, 4]]]})


def test_polygon_from_shapely():
    shapely = pytest.importorskip("shapely.geometry", reason="python3-shapely is not installed")
    box = shapely.box(0, 0, 3, 1)
    polygon = convexloc.Polygon(box)
    assert sorted(map(tuple, polygon.vertices.tolist())) == [(0, 0), (0, 1), (3, 0), (3, 1)]


def exact_hull_checks(points, polygon):
    """Every point inside or on the hull (rationally), every vertex one of the points."""
    vertices = polygon.vertices
    assert set(map(tuple, vertices.tolist())) <= set(map(tuple, points.tolist()))
    n = len(vertices)
    for p in points:
        assert min(orient2d_exact(vertices[i], vertices[(i + 1) % n], p) for i in range(n)) >= 0


def test_polygon_hull_is_exact():
    rng = np.random.default_rng(11)
    inner = rng.integers(-4, 13, size=(400, 2)).astype(float)
    inner = inner[convexloc.covers(LATTICE_OCTAGON, inner)]
    lattice = np.concatenate([inner, on_edges_lattice(LATTICE_OCTAGON)])
    hull = convexloc.Polygon.hull(lattice)
    exact_hull_checks(lattice, hull)
    assert hull == convexloc.Polygon(LATTICE_OCTAGON)  # collinear edge points are not vertices
    # nearly collinear doubles: a point one ulp off a long edge decides the hull exactly
    a, b = np.array([0.1, 0.1]), np.array([0.7, 0.3])
    mid = (a + b) / 2
    off = np.array([mid[0], np.nextafter(mid[1], -1)])
    points = np.array([a, b, [0.2, 0.9], mid, off])
    hull = convexloc.Polygon.hull(points)
    exact_hull_checks(points, hull)
    side = orient2d_exact(a, b, off)
    assert (tuple(off) in set(map(tuple, hull.vertices.tolist()))) == (side < 0)


@pytest.mark.parametrize("points, message", [
    (np.zeros((0, 2)), "a hull needs at least 3 points not on one line, got 0 points"),
    ([[1, 1]], "a hull needs at least 3 points not on one line, got 1 point"),
    ([[0, 0], [1, 1], [2, 2], [3, 3]], "the hull of the 4 points has no area: they all lie on one line"),
    ([[0, 0], [1, np.nan], [2, 0]], r"points\[1\] = \(1.0, nan\) is not finite"),
])
def test_polygon_hull_errors(points, message):
    with pytest.raises(convexloc.GeometryError, match=message):
        convexloc.Polygon.hull(points)


@pytest.mark.parametrize("make", [convexloc.Polyhedron.hull,
                                  lambda p: convexloc.hull_covers(p, [[0, 0, 0]])])
def test_3d_hull_of_too_few_points_names_the_count(make):
    with pytest.raises(convexloc.GeometryError,
                       match=r"^a hull needs at least 4 points not in one plane, got 0 points$"):
        make(np.zeros((0, 3)))
    with pytest.raises(convexloc.GeometryError, match="got 3 points$"):
        make(np.eye(3))


def test_argument_errors_name_the_numbers_given(square):
    with pytest.raises(ValueError, match=r"^resolution must be from 0 \(chosen from the shape\) "
                                         r"to 4294967295, got 4611686018427387904$"):
        convexloc.PolarLocator(square, resolution=2**62)
    with pytest.raises(ValueError, match="got -1$"):
        convexloc.UniformLocator(square, -1)
    with pytest.raises(TypeError, match="resolution must be an integer, got 2.5"):
        convexloc.PolarLocator(square, 2.5)
    # anything Polygon() takes, vertices too; what is no polygon says what a polygon can be
    assert convexloc.PolarLocator([[0, 0], [1, 0], [0, 1]]).shape == convexloc.Polygon(
        [[0, 0], [1, 0], [0, 1]])
    with pytest.raises(TypeError, match=r"polygon must be numbers .*got a boolean array"):
        convexloc.PolarLocator([[True, False]])
    assert convexloc.PolarLocator(square, np.int64(3)).slabs_per_octant == 3
