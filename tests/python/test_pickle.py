"""Shapes and locators travel: pickle, copy and deepcopy round trips keep the exact doubles,
the history and the answers; equal shapes compare (and hash) equal; arrays are read-only."""

import copy
import functools
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


# === a cube map's pickle carries its tables

def tall_cylinder(sides=600, height=40.0):
    """A cylinder of radius 1 and the given height as CAD programs export it: side quads split
    in two, each cap fanned from one corner (crowded cells: a zone of thin side faces)."""
    angle = 2 * np.pi * np.arange(sides) / sides
    ring = np.column_stack([np.cos(angle), np.sin(angle)])
    vertices = np.vstack([np.column_stack([ring, np.full(sides, -height / 2)]),
                          np.column_stack([ring, np.full(sides, height / 2)])])
    k = np.arange(sides)
    nxt = (k + 1) % sides
    sides_ = np.vstack([np.column_stack([k, nxt, nxt + sides]),
                        np.column_stack([k, nxt + sides, k + sides])])
    fan = np.arange(1, sides - 1)
    bottom = np.column_stack([np.zeros_like(fan), fan + 1, fan])
    top = np.column_stack([np.full_like(fan, sides), fan + sides, fan + sides + 1])
    return convexloc.Polyhedron(vertices, np.vstack([sides_, bottom, top]))


@functools.cache
def cubemap_shapes():
    rng = np.random.default_rng(8)
    cloud = rng.normal(size=(1500, 3))
    return {
        "sphere": convexloc.Polyhedron.hull(cloud / np.linalg.norm(cloud, axis=1)[:, None]),
        "box": convexloc.Polyhedron.hull(rng.uniform(-1, 1, (400, 3)) * [5, 1, 0.01]),
        "tall-cylinder": tall_cylinder(),
    }


def hard_points_3d(shape, locator, rng):
    """Random points, the vertices and their ulp neighbours, points on the triangles
    (barycentric mixes, within rounding of the faces) and their neighbours, the centre and its
    neighbours, rays from the centre through vertices."""
    v, tri = shape.vertices, shape.triangles
    weights = rng.dirichlet([1, 1, 1], len(tri))
    on_faces = np.einsum("fk,fkd->fd", weights, v[tri])
    centre = np.array([locator.centre])
    scale = np.linspace(0, 1.5, 13)[:, None, None]
    rays = (centre + scale * (v[:: max(1, len(v) // 50)] - centre)).reshape(-1, 3)
    lo, hi = v.min(axis=0), v.max(axis=0)
    box = rng.uniform(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo), (3000, 3))
    return np.concatenate([box, ulp_ring(v), ulp_ring(on_faces), ulp_ring(centre, 2), rays])


@pytest.mark.parametrize("trip", ROUND_TRIPS)
@pytest.mark.parametrize("name", ["sphere", "box", "tall-cylinder"])
def test_a_cube_map_loads_its_tables_without_building(name, trip):
    shape = cubemap_shapes()[name]
    locator = convexloc.CubemapLocator(shape)
    back = ROUND_TRIPS[trip](locator)
    assert not locator.loaded and back.loaded  # loaded from the tables, not built
    assert back.shape == shape
    before, after = locator.stats(), back.stats()
    assert after["build_seconds"] == before["build_seconds"]  # the build's, carried
    for key in ("cells", "nodes", "entries", "max_level", "zone_cells", "sector_cells"):
        assert after[key] == before[key], key
    assert after["bytes"] <= before["bytes"]  # the same tables, without the build's spare room
    if name == "tall-cylinder":
        assert before["zone_cells"] + before["crowded_cells"] > 0  # the crowded tables travel
    assert (back.resolution, back.centre, back.cube_half_size) == (
        locator.resolution, locator.centre, locator.cube_half_size)
    points = hard_points_3d(shape, locator, np.random.default_rng(9))
    want = locator.locate(points)
    np.testing.assert_array_equal(back.locate(points), want)
    assert set(np.unique(want)) == {convexloc.INSIDE, convexloc.BOUNDARY, convexloc.OUTSIDE}
    assert back.locate(np.array([locator.centre]))[0] == convexloc.INSIDE


def test_the_tables_travel_as_compact_arrays(polyhedron):
    version, shape, resolution, tables = convexloc.CubemapLocator(polyhedron, 7).__getstate__()
    assert version == 2 and shape is polyhedron and resolution == 7
    assert tables["version"] == 1 and tables["resolution"] == 7
    assert tables["nodes"].dtype == np.uint32 and tables["nodes"].shape[1] == 2
    assert tables["radii"].dtype == np.float32 and tables["radii"].shape == tables["nodes"].shape
    assert tables["entries"].dtype == np.uint32 and tables["entries"].ndim == 1
    assert len(tables["nodes"]) >= 6 * 7 * 7


def cubemap_state():
    return convexloc.CubemapLocator(tall_cylinder(200, 10.0)).__getstate__()


def load(state):
    locator = convexloc.CubemapLocator.__new__(convexloc.CubemapLocator)
    locator.__setstate__(state)
    return locator


def damaged(state, table, change):
    version, shape, resolution, tables = state
    tables = dict(tables)
    tables[table] = change(tables[table].copy()) if table in tables else change(None)
    return (version, shape, resolution, tables)


def first_plain_leaf(nodes):
    return next(k for k, (first, count) in enumerate(nodes) if 0 < count < 2**30)


def test_damaged_tables_are_refused_by_name():
    state = cubemap_state()
    nodes, faces = state[3]["nodes"], state[1].face_count

    def out_of_range(entries):
        entries[nodes[first_plain_leaf(nodes)][0]] = 2**31 - 1
        return entries

    def past_the_end(table):
        table[first_plain_leaf(nodes)][0] = len(state[3]["entries"])
        return table

    cases = [
        ("entries", out_of_range, "lists face 2147483647"),
        ("nodes", past_the_end, "run past"),
        ("radii", lambda a: a[:-1], "radii holds"),
        ("entries", lambda a: a[: len(a) // 2], "entries"),
        ("nodes", lambda a: a[:-4], "radii holds"),
        ("zone_ranges", lambda a: a + np.uint32(1 << 20), "zone range 0"),
    ]
    assert faces < 2**31 - 1
    for table, change, expected in cases:
        with pytest.raises(convexloc.ParseError, match=expected):
            load(damaged(state, table, change))
    # the wrong dtype, or a table missing: a ValueError saying which
    with pytest.raises(ValueError, match="'radii' is not a numpy array of float32"):
        load(damaged(state, "radii", lambda a: a.astype(np.float64)))
    version, shape, resolution, tables = state
    with pytest.raises(ValueError, match="lack 'entries'"):
        load((version, shape, resolution, {k: v for k, v in tables.items() if k != "entries"}))
    with pytest.raises(convexloc.ParseError, match="strictly inside"):
        load((version, shape, resolution, dict(tables, centre=tuple(shape.vertices[0]))))


def test_older_states_and_other_versions_of_the_tables_are_rebuilt():
    shape = tall_cylinder(200, 10.0)
    locator = convexloc.CubemapLocator(shape, 9)
    points = hard_points_3d(shape, locator, np.random.default_rng(4))
    version, _, resolution, tables = locator.__getstate__()
    for state in [(1, shape, resolution), (version, shape, resolution, dict(tables, version=99))]:
        back = load(state)
        assert not back.loaded and back.resolution == locator.resolution
        np.testing.assert_array_equal(back.locate(points), locator.locate(points))
