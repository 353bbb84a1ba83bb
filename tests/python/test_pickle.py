"""Shapes and locators travel: pickle, copy and deepcopy round trips keep the exact doubles,
the history and the answers; equal shapes compare (and hash) equal; arrays are read-only."""

import copy
import pickle

import numpy as np
import pytest

import convexloc
from conftest import LATTICE_OCTAGON, adversarial_points_2d, ulp_ring

ROUND_TRIPS = {
    "pickle": lambda x: pickle.loads(pickle.dumps(x)),
    "pickle-0": lambda x: pickle.loads(pickle.dumps(x, protocol=0)),
    "pickle-1": lambda x: pickle.loads(pickle.dumps(x, protocol=1)),
    "copy": copy.copy,
    "deepcopy": copy.deepcopy,
}


@pytest.fixture
def polygon():
    # clockwise, with a repeated and a collinear vertex: the history is not trivial
    v = np.insert(LATTICE_OCTAGON, 1, [4, 0], axis=0)[::-1]
    return convexloc.Polygon(np.insert(v, 5, v[4], axis=0))


@pytest.fixture
def polyhedron():
    rng = np.random.default_rng(3)
    cloud = rng.normal(size=(300, 3))
    return convexloc.Polyhedron.hull(cloud / np.linalg.norm(cloud, axis=1)[:, None])


@pytest.mark.parametrize("trip", ROUND_TRIPS)
def test_polygon_round_trip(polygon, trip):
    assert polygon.dropped_count == 2 and polygon.was_clockwise
    back = ROUND_TRIPS[trip](polygon)
    assert type(back) is convexloc.Polygon and back is not polygon
    assert back == polygon and hash(back) == hash(polygon)
    assert back.vertices.tobytes() == polygon.vertices.tobytes()
    np.testing.assert_array_equal(back.source_index, polygon.source_index)
    assert (back.dropped_count, back.was_clockwise) == (2, True)
    twice = ROUND_TRIPS[trip](back)
    np.testing.assert_array_equal(twice.source_index, polygon.source_index)


@pytest.mark.parametrize("trip", ROUND_TRIPS)
def test_polyhedron_round_trip(polyhedron, trip):
    back = ROUND_TRIPS[trip](polyhedron)
    assert type(back) is convexloc.Polyhedron and back == polyhedron
    assert hash(back) == hash(polyhedron)
    assert back.vertices.tobytes() == polyhedron.vertices.tobytes()
    for name in ("triangles", "neighbours", "source_face", "source_vertex"):
        np.testing.assert_array_equal(getattr(back, name), getattr(polyhedron, name))
    assert back.centre == polyhedron.centre and back.was_inverted == polyhedron.was_inverted


@pytest.mark.parametrize("trip", ROUND_TRIPS)
@pytest.mark.parametrize("cls", list(convexloc.LOCATORS_2D.values()))
def test_2d_locator_round_trip(polygon, cls, trip):
    locator = cls(polygon, 5) if cls in (convexloc.UniformLocator, convexloc.PolarLocator) else cls(polygon)
    back = ROUND_TRIPS[trip](locator)
    assert type(back) is cls and back.shape == polygon
    points = adversarial_points_2d(polygon.vertices, locator)
    np.testing.assert_array_equal(back.locate(points), locator.locate(points))
    assert back.stats()["cells"] == locator.stats()["cells"]  # the same resolution


@pytest.mark.parametrize("trip", ROUND_TRIPS)
@pytest.mark.parametrize("cls", list(convexloc.LOCATORS_3D.values()))
def test_3d_locator_round_trip(polyhedron, cls, trip):
    locator = cls(polyhedron, 7) if cls is convexloc.CubemapLocator else cls(polyhedron)
    back = ROUND_TRIPS[trip](locator)
    assert type(back) is cls and back.shape == polyhedron
    rng = np.random.default_rng(5)
    points = np.concatenate([ulp_ring(polyhedron.vertices), rng.uniform(-1.2, 1.2, (3000, 3))])
    np.testing.assert_array_equal(back.locate(points), locator.locate(points))
    assert back.stats()["cells"] == locator.stats()["cells"]


def test_a_pickled_locator_carries_its_shape_once(polyhedron):
    locators = [convexloc.HalfspaceLocator(polyhedron), convexloc.CubemapLocator(polyhedron)]
    back = pickle.loads(pickle.dumps(locators))
    assert back[0].shape is back[1].shape  # pickle's memo shares the one shape


def test_polygon_equality_is_the_cyclic_vertex_order():
    square = convexloc.Polygon([[0, 0], [1, 0], [1, 1], [0, 1]])
    assert square == convexloc.Polygon([[1, 1], [0, 1], [0, 0], [1, 0]])  # another start
    assert square == convexloc.Polygon([[0, 1], [1, 1], [1, 0], [0, 0]])  # clockwise input
    assert square == convexloc.Polygon([[0, -0.0], [1, 0], [1, 1], [0, 1]])  # -0 is 0
    assert hash(square) == hash(convexloc.Polygon([[0, 1], [0, 0], [1, 0], [1, 1]]))
    nudged = convexloc.Polygon([[0, 0], [1, 0], [1, np.nextafter(1, 2)], [0, 1]])
    assert square != nudged and not (square == nudged)
    assert square != convexloc.Polygon([[0, 0], [1, 0], [0, 1]])
    assert square != "square" and square != square.vertices.tolist()
    assert len({square, convexloc.Polygon([[1, 0], [1, 1], [0, 1], [0, 0]]), nudged}) == 2


def test_polyhedron_equality_ignores_the_order_of_vertices_and_triangles(cube):
    rng = np.random.default_rng(2)
    shuffled = convexloc.Polyhedron(cube.vertices[::-1].copy(),
                                    (len(cube.vertices) - 1 - cube.triangles)[rng.permutation(12)])
    assert shuffled == cube and hash(shuffled) == hash(cube)
    moved = cube.vertices * (1 + 2**-52)  # one ulp larger, every corner
    assert convexloc.Polyhedron(moved, cube.triangles) != cube
    assert cube != convexloc.Polygon([[0, 0], [1, 0], [0, 1]])


def test_arrays_are_read_only_views(square, cube):
    for shape in (square, cube):
        with pytest.raises(ValueError, match="read-only"):
            shape.vertices[0, 0] = 5
        assert shape.vertices.base is not None  # a view, not a copy
    for name in ("triangles", "neighbours", "source_face", "source_vertex"):
        with pytest.raises(ValueError, match="read-only"):
            getattr(cube, name)[0] = 1
    with pytest.raises(ValueError, match="read-only"):
        square.source_index[0] = 3
    view = square.vertices
    del square  # the view keeps the shape's memory alive
    assert view.tolist() == [[0, 0], [1, 0], [1, 1], [0, 1]]


def test_a_foreign_state_is_refused():
    polygon = convexloc.Polygon.__new__(convexloc.Polygon)
    with pytest.raises(ValueError, match="pickled by another version"):
        polygon.__setstate__((99, np.zeros((3, 2)), ()))


def test_index_histories_travel_as_uint32_and_come_back_int64():
    cloud = np.random.default_rng(5).normal(size=(200, 3))
    hull = convexloc.Polyhedron.hull(cloud)
    version, vertices, triangles, history = hull.__getstate__()
    assert version == 2 and triangles.dtype == np.uint32
    assert history[0].dtype == np.uint32 and history[1].dtype == np.uint32
    assert history[0].nbytes == 4 * hull.face_count
    back = pickle.loads(pickle.dumps(hull))
    for name in ("source_face", "source_vertex"):
        restored, original = getattr(back, name), getattr(hull, name)
        assert restored.dtype == np.int64 and not restored.flags.writeable
        np.testing.assert_array_equal(restored, original)
    # a state of the first version (int64 histories) still loads
    old = (1, vertices, triangles, (hull.source_face, hull.source_vertex, hull.was_inverted))
    again = convexloc.Polyhedron.__new__(convexloc.Polyhedron)
    again.__setstate__(old)
    assert again == hull and again.source_face.dtype == np.int64
    np.testing.assert_array_equal(again.source_vertex, hull.source_vertex)
