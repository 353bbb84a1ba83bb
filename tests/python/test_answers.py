"""The module answers as the C++ locators do, on random and adversarial points, and exactly."""

import numpy as np
import pytest

import convexloc
from conftest import (
    LATTICE_OCTAGON,
    adversarial_points_2d,
    locate_exact_2d,
    on_edges_lattice,
    reference_answers,
    regular_polygon,
    special_values,
    ulp_ring,
    write_off,
    write_polygon,
)

METHODS_2D = list(convexloc.LOCATORS_2D)
METHODS_3D = list(convexloc.LOCATORS_3D)


def random_convex(n, seed):
    """The hull of n random points on a circle, perturbed (vertices are generic doubles)."""
    rng = np.random.default_rng(seed)
    t = np.sort(rng.uniform(0, 2 * np.pi, n))
    return np.column_stack([np.cos(t), np.sin(t)]) * 3.0 + [0.25, -1.5]


POLYGONS = {
    "lattice_octagon": LATTICE_OCTAGON,
    "heptagon": regular_polygon(7),
    "1000-gon": regular_polygon(1000, radius=1e3, centre=(5e2, -3e2)),
    "random_300": random_convex(300, 3),
}


def query_points_2d(vertices, locator):
    rng = np.random.default_rng(11)
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    span = hi - lo
    random = rng.uniform(lo - 0.2 * span, hi + 0.2 * span, size=(20000, 2))
    return np.concatenate([random, adversarial_points_2d(vertices, locator)])


@pytest.mark.parametrize("method", METHODS_2D)
@pytest.mark.parametrize("name", list(POLYGONS))
def test_2d_equals_cpp(method, name, tmp_path):
    vertices = POLYGONS[name]
    polygon = convexloc.Polygon(vertices)
    locator = convexloc.LOCATORS_2D[method](polygon)
    points = query_points_2d(vertices, locator)
    expected = reference_answers(write_polygon(tmp_path / "p.txt", vertices), points, method,
                                 tmp_path=tmp_path)
    got = locator.locate(points)
    assert got.dtype == np.int8 and got.shape == (len(points),)
    np.testing.assert_array_equal(got, expected)
    np.testing.assert_array_equal(locator.locate_xy(points[:, 0], points[:, 1]), expected)


@pytest.mark.parametrize("method", ["uniform", "polar"])
def test_2d_resolutions_equal_cpp(method, tmp_path):
    vertices = POLYGONS["random_300"]
    polygon = convexloc.Polygon(vertices)
    for resolution in (1, 3, 64):
        locator = convexloc.LOCATORS_2D[method](polygon, resolution=resolution)
        points = query_points_2d(vertices, locator)
        expected = reference_answers(write_polygon(tmp_path / "p.txt", vertices), points, method,
                                     resolution, tmp_path=tmp_path)
        np.testing.assert_array_equal(locator.locate(points), expected)


@pytest.mark.parametrize("method", METHODS_2D)
def test_2d_exact_on_lattice_edges(method):
    """Points exactly on edges are BOUNDARY, one ulp off them INSIDE or OUTSIDE, as rational
    arithmetic says."""
    locator = convexloc.LOCATORS_2D[method](convexloc.Polygon(LATTICE_OCTAGON))
    on = on_edges_lattice(LATTICE_OCTAGON)
    assert np.all(locator.locate(on) == convexloc.BOUNDARY)
    near = np.concatenate([ulp_ring(on, 1), ulp_ring(on * 1e-3, 1), special_values(2)])
    octagon_small = convexloc.Polygon(LATTICE_OCTAGON * 1e-3)
    small = convexloc.LOCATORS_2D[method](octagon_small)
    exact = locate_exact_2d(LATTICE_OCTAGON, near)
    np.testing.assert_array_equal(locator.locate(near), exact)
    np.testing.assert_array_equal(small.locate(near),
                                  locate_exact_2d(octagon_small.vertices, near))


@pytest.mark.parametrize("method", METHODS_2D)
def test_2d_trace_agrees_with_locate(method):
    vertices = POLYGONS["heptagon"]
    locator = convexloc.LOCATORS_2D[method](convexloc.Polygon(vertices))
    points = query_points_2d(vertices, locator)[::97]
    codes = locator.locate(points)
    for p, code in zip(points, codes):
        trace = locator.trace(p)
        assert trace["result"] == code
        assert trace["location"] is convexloc.Location(code)  # the value locate gives
        assert trace["location_name"] == convexloc.NAMES[code]
        assert trace["method"] == method


# === 3D


def cube_points():
    """Integer points on, in and around the cube [-2, 2]^3, its vertices' ulp rings, and
    special values."""
    g = np.arange(-3, 4, dtype=float)
    lattice = np.stack(np.meshgrid(g, g, g), axis=-1).reshape(-1, 3)
    corners = np.array([[x, y, z] for x in (-2.0, 2.0) for y in (-2.0, 2.0) for z in (-2.0, 2.0)])
    return np.concatenate([lattice, ulp_ring(corners, 1), ulp_ring(lattice / 2, 1),
                           special_values(3)])


def hull_points(seed, count):
    rng = np.random.default_rng(seed)
    cloud = rng.normal(size=(count, 3))
    return cloud / np.linalg.norm(cloud, axis=1)[:, None] * [3.0, 2.0, 1.0]


def polyhedron_cases():
    cube = convexloc.Polyhedron.hull(
        [[x, y, z] for x in (-2.0, 2.0) for y in (-2.0, 2.0) for z in (-2.0, 2.0)])
    return {"cube": cube, "hull_500": convexloc.Polyhedron.hull(hull_points(5, 500))}


@pytest.mark.parametrize("method", METHODS_3D)
@pytest.mark.parametrize("name", ["cube", "hull_500"])
def test_3d_equals_cpp(method, name, tmp_path):
    polyhedron = polyhedron_cases()[name]
    locator = convexloc.LOCATORS_3D[method](polyhedron)
    v = polyhedron.vertices
    rng = np.random.default_rng(2)
    lo, hi = v.min(axis=0), v.max(axis=0)
    faces = v[polyhedron.triangles]
    points = np.concatenate([
        rng.uniform(lo - 0.3 * (hi - lo), hi + 0.3 * (hi - lo), size=(20000, 3)),
        ulp_ring(v, 1), ulp_ring(faces.mean(axis=1), 1), ulp_ring((faces[:, 0] + faces[:, 1]) / 2, 1),
        cube_points(), special_values(3)])
    off = write_off(tmp_path / "shape.off", v, polyhedron.triangles)
    expected = reference_answers(off, points, method, tmp_path=tmp_path)
    np.testing.assert_array_equal(locator.locate(points), expected)
    np.testing.assert_array_equal(locator.locate_xyz(*points.T), expected)
    for p in points[::301]:
        assert locator.trace(p)["result"] == locator.locate([p])[0]


def test_3d_cubemap_resolutions_equal_cpp(tmp_path):
    polyhedron = polyhedron_cases()["hull_500"]
    v = polyhedron.vertices
    points = np.concatenate([np.random.default_rng(4).uniform(-3.5, 3.5, (20000, 3)), ulp_ring(v, 1)])
    off = write_off(tmp_path / "shape.off", v, polyhedron.triangles)
    for resolution in (1, 2, 37):
        locator = convexloc.CubemapLocator(polyhedron, resolution=resolution)
        assert 1 <= locator.resolution <= resolution  # a budget may coarsen it
        expected = reference_answers(off, points, "cubemap", resolution, tmp_path=tmp_path)
        np.testing.assert_array_equal(locator.locate(points), expected)


@pytest.mark.parametrize("method", METHODS_3D)
def test_3d_exact_on_cube_lattice(method):
    cube = convexloc.Polyhedron.hull(
        [[x, y, z] for x in (-2.0, 2.0) for y in (-2.0, 2.0) for z in (-2.0, 2.0)])
    locator = convexloc.LOCATORS_3D[method](cube)
    points = cube_points()[:343]  # the integer lattice
    expected = np.where(np.all(np.abs(points) < 2, axis=1), convexloc.INSIDE,
                        np.where(np.all(np.abs(points) <= 2, axis=1), convexloc.BOUNDARY,
                                 convexloc.OUTSIDE))
    np.testing.assert_array_equal(locator.locate(points), expected)


def test_assets_equal_cpp(tmp_path):
    from conftest import env_path
    assets = env_path("CONVEXLOC_ASSETS")
    for path in sorted(assets.glob("*.off")) + sorted(assets.glob("*.obj")):
        polyhedron = convexloc.read_polyhedron(path)
        v = polyhedron.vertices
        rng = np.random.default_rng(9)
        points = np.concatenate([rng.uniform(v.min(axis=0) * 1.2, v.max(axis=0) * 1.2, (5000, 3)),
                                 ulp_ring(v, 1)])
        for method in METHODS_3D:
            locator = convexloc.LOCATORS_3D[method](polyhedron)
            expected = reference_answers(path, points, method, tmp_path=tmp_path)
            np.testing.assert_array_equal(locator.locate(points), expected, err_msg=str(path))


def test_conveniences_equal_locators():
    vertices = POLYGONS["random_300"]
    polar = convexloc.PolarLocator(convexloc.Polygon(vertices))
    points = query_points_2d(vertices, polar)
    codes = polar.locate(points)
    np.testing.assert_array_equal(convexloc.covers(vertices, points), codes != convexloc.OUTSIDE)
    np.testing.assert_array_equal(convexloc.contains(vertices, points), codes == convexloc.INSIDE)
    cloud = hull_points(8, 300)
    hull = convexloc.Polyhedron.hull(cloud)
    cubemap = convexloc.CubemapLocator(hull)
    q = np.concatenate([np.random.default_rng(1).uniform(-3, 3, (5000, 3)), ulp_ring(hull.vertices)])
    codes = cubemap.locate(q)
    np.testing.assert_array_equal(convexloc.hull_covers(cloud, q), codes != convexloc.OUTSIDE)
    np.testing.assert_array_equal(convexloc.hull_contains(hull, q), codes == convexloc.INSIDE)


def test_2d_trace_steps_and_paper_mode():
    """The trace tells the slab search's probes, eq. (4)'s numbers and the polar index; with
    radii=False the polar cell's edges decide, with the same answer."""
    vertices = POLYGONS["heptagon"]
    polygon = convexloc.Polygon(vertices)
    slab = convexloc.LOCATORS_2D["slab"](polygon)
    centre = np.mean(vertices, axis=0)
    t = slab.trace(centre)
    assert len(t["probes"]) >= 1
    ys = sorted(set(float(v[1]) for v in vertices))
    for rank, y, above in t["probes"]:
        assert ys[rank] == y
        assert above == (centre[1] >= y)
    uniform = convexloc.LOCATORS_2D["uniform"](polygon)
    u = uniform.trace(centre)["uniform"]
    assert u["slabs"] > 0
    assert int(u["value"]) == uniform.trace(centre)["cell"]
    polar = convexloc.LOCATORS_2D["polar"](polygon)
    points = query_points_2d(vertices, polar)[::53]
    tested = 0
    for p in points:
        fast, paper = polar.trace(p), polar.trace(p, radii=False)
        assert paper["result"] == fast["result"] == polar.locate([p])[0]
        assert not paper["radius_filter"] and not paper["by_radius"]
        if paper["cell"] >= 0:
            assert paper["polar"]["slabs"] == polar.slabs_per_octant
            tested += len(paper["edges"]) + len(paper["rays"]) > 0
    assert tested > 0
