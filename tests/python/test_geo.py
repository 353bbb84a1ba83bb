"""Geometries in and out: every class and function that takes a polygon takes a Shapely
polygon, any __geo_interface__ and GeoJSON mappings (z dropped; holes, several parts and
other types refused with what they are); Polygon and Polyhedron give a __geo_interface__;
bounds is in Shapely's order. Also the argument errors a data scientist meets first."""

import numpy as np
import pytest

import convexloc
from conftest import LATTICE_OCTAGON, locate_exact_2d

shapely_geometry = pytest.importorskip("shapely.geometry")

OCTAGON = shapely_geometry.Polygon(LATTICE_OCTAGON)
POINTS = np.concatenate([LATTICE_OCTAGON, [[4, 6], [12, 6], [13, 6], [-4, 0]],
                         np.random.default_rng(0).uniform(-6, 14, size=(500, 2))])
TRUTH = locate_exact_2d(LATTICE_OCTAGON, POINTS)


class Footprint:
    """Not Shapely: any object with a __geo_interface__."""

    def __init__(self, mapping):
        self.__geo_interface__ = mapping


def geojson(ring):
    return {"type": "Polygon", "coordinates": [[list(p) for p in ring] + [list(ring[0])]]}


@pytest.mark.parametrize("method", list(convexloc.LOCATORS_2D))
def test_every_2d_locator_takes_a_shapely_polygon(method):
    locator = convexloc.LOCATORS_2D[method](OCTAGON)
    assert isinstance(locator.shape, convexloc.Polygon)
    np.testing.assert_array_equal(locator.locate(POINTS), TRUTH)


@pytest.mark.parametrize("geometry", [
    OCTAGON, Footprint(geojson(LATTICE_OCTAGON)), geojson(LATTICE_OCTAGON),
    {"type": "Feature", "properties": {}, "geometry": geojson(LATTICE_OCTAGON)},
    {"type": "MultiPolygon", "coordinates": [geojson(LATTICE_OCTAGON)["coordinates"]]},
    shapely_geometry.Polygon([(x, y, 7.5 + x) for x, y in LATTICE_OCTAGON]),  # z dropped
])
def test_contains_and_covers_take_geometries(geometry):
    inside = TRUTH == convexloc.INSIDE
    np.testing.assert_array_equal(convexloc.contains(geometry, POINTS), inside)
    np.testing.assert_array_equal(convexloc.covers(geometry, POINTS), TRUTH != convexloc.OUTSIDE)
    assert convexloc.Polygon(geometry) == convexloc.Polygon(LATTICE_OCTAGON)


def test_the_chunked_and_dask_paths_take_geometries():
    np.testing.assert_array_equal(convexloc.locate_chunks(POINTS, OCTAGON, chunk=100), TRUTH)
    on_dask = pytest.importorskip("convexloc.dask")
    codes = on_dask.locate(POINTS, geojson(LATTICE_OCTAGON)).compute()
    np.testing.assert_array_equal(codes, TRUTH)


@pytest.mark.parametrize("geometry, error, message", [
    (shapely_geometry.Polygon([(0, 0), (9, 0), (9, 9), (0, 9)], [[(1, 1), (2, 1), (2, 2)]]),
     convexloc.GeometryError, r"1 interior ring\(s\): a convex polygon has no holes"),
    (shapely_geometry.MultiPolygon([OCTAGON, shapely_geometry.Polygon([(20, 0), (21, 0),
                                                                       (20, 1)])]),
     convexloc.GeometryError, r"a MultiPolygon of 2 parts: .* one by one"),
    (shapely_geometry.LineString([(0, 0), (1, 1)]), TypeError, r"got type 'LineString'"),
    ({"type": "FeatureCollection", "features": []}, TypeError, r"FeatureCollection"),
    ({"type": "Polygon", "coordinates": [[[0], [1, 0], [0, 1]]]}, convexloc.GeometryError,
     r"position 0 has 1 coordinate"),
    (convexloc.Polyhedron.hull([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]), TypeError,
     r"polygon must be a polygon .* got a Polyhedron"),
])
def test_what_a_polygon_cannot_be(geometry, error, message):
    with pytest.raises(error, match=message):
        convexloc.PolarLocator(geometry)
    with pytest.raises(error, match=message):
        convexloc.covers(geometry, POINTS)


def test_geo_interface_out():
    polygon = convexloc.Polygon(LATTICE_OCTAGON[::-1])  # clockwise in, counter-clockwise kept
    geo = polygon.__geo_interface__
    assert geo["type"] == "Polygon" and len(geo["coordinates"]) == 1
    ring = geo["coordinates"][0]
    assert ring[0] == ring[-1] and len(ring) == len(polygon) + 1
    back = shapely_geometry.shape(polygon)
    assert back.exterior.is_ccw and back.equals(OCTAGON) and back.area == polygon.area
    assert convexloc.Polygon(back) == polygon
    assert polygon.bounds == OCTAGON.bounds == (-4.0, 0.0, 12.0, 12.0)  # Shapely's order

    cube = convexloc.Polyhedron.hull([[x, y, z] for x in (0, 1) for y in (0, 2)
                                      for z in (0, 3)])
    assert cube.bounds == (0.0, 0.0, 0.0, 1.0, 2.0, 3.0)
    solid = shapely_geometry.shape(cube)
    assert solid.geom_type == "MultiPolygon" and solid.has_z
    assert len(solid.geoms) == cube.face_count
    for part, triangle in zip(solid.geoms, cube.triangles):
        np.testing.assert_array_equal(np.asarray(part.exterior.coords)[:3],
                                      cube.vertices[triangle])


def test_geopandas_reads_convexloc_polygons():
    geopandas = pytest.importorskip("geopandas")
    series = geopandas.GeoSeries([shapely_geometry.shape(convexloc.Polygon(LATTICE_OCTAGON))])
    assert tuple(series.total_bounds) == OCTAGON.bounds
    assert convexloc.PolarLocator(series.iloc[0]).locate([[4, 6]])[0] == convexloc.INSIDE


# === The argument errors


def test_workers_default_and_range():
    polar = convexloc.PolarLocator(OCTAGON)
    with pytest.raises(ValueError) as e:
        polar.locate(POINTS, workers=10**6)
    assert str(e.value) == ("workers must be a thread count from 1 to 4096, or -1 for every "
                            "core (-2 every core but one, ...), got 1000000")
    with pytest.raises(ValueError, match=r"\.\.\.\), not 0$"):
        polar.locate(POINTS, workers=0)


def test_python_ints_beyond_int64_are_exact_or_refused():
    polar = convexloc.PolarLocator(OCTAGON)
    assert polar.locate([[2**70, 1], [4, 6]]).tolist() == [convexloc.OUTSIDE, convexloc.INSIDE]
    with pytest.raises(ValueError, match=r"points\[0, 0\] = 1180591620717411303425 is not "
                                         r"exactly a float64 \(the nearest is "
                                         r"1\.1805916207174113e\+21\)"):
        polar.locate([[2**70 + 1, 1]])
    with pytest.raises(ValueError, match=r"beyond the largest float64"):
        polar.locate([[10**400, 1]])


def test_pandas_nullable_floats():
    pandas = pytest.importorskip("pandas")
    polar = convexloc.PolarLocator(OCTAGON)
    x = pandas.array([4.0, 13.0], dtype="Float64")
    assert polar.locate_xy(x, x - 1).tolist() == [convexloc.INSIDE, convexloc.OUTSIDE]
    with pytest.raises(TypeError, match=r"x\[1\] is a missing value \(<NA>\): .*dropna.*"
                                        r"na_value=numpy\.nan"):
        polar.locate_xy(pandas.array([4.0, None], dtype="Float64"), [1.0, 2.0])
