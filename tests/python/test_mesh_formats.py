"""read_polyhedron on STL and PLY files, and hull=True on meshes and point clouds."""

import numpy as np
import pytest

import convexloc
from conftest import env_path


def sorted_rows(a):
    return sorted(map(tuple, np.asarray(a).tolist()))


def test_stl_and_ply_read_as_the_off():
    assets = env_path("CONVEXLOC_ASSETS")
    off = convexloc.read_polyhedron(assets / "cube.off")
    ply = convexloc.read_polyhedron(assets / "cube.ply")
    assert sorted_rows(ply.vertices) == sorted_rows(off.vertices)
    assert ply.face_count == off.face_count
    cylinder = convexloc.read_polyhedron(str(assets / "cylinder-64.stl"))
    assert cylinder.vertex_count == 128
    assert not cylinder.was_inverted


def test_hull_of_a_point_cloud():
    cloud = env_path("CONVEXLOC_ASSETS") / "sphere-cloud.ply"
    with pytest.raises(convexloc.GeometryError, match="no faces.*hull=True") as caught:
        convexloc.read_polyhedron(cloud)
    assert caught.value.path == str(cloud)
    hull = convexloc.read_polyhedron(cloud, hull=True)
    # the 600 points on the sphere are its vertices; the 200 inside are not
    assert hull.vertex_count == 600
    assert np.all(np.linalg.norm(hull.vertices, axis=1) > 0.999)


def test_hull_of_a_mesh_is_the_mesh():
    assets = env_path("CONVEXLOC_ASSETS")
    mesh = convexloc.read_polyhedron(assets / "cylinder-64.stl")
    hull = convexloc.read_polyhedron(assets / "cylinder-64.stl", hull=True)
    assert sorted_rows(hull.vertices) == sorted_rows(mesh.vertices)
    with pytest.raises(TypeError):
        convexloc.read_polyhedron(assets / "cube.ply", True)


def test_binary_errors_name_the_byte(tmp_path):
    bad = tmp_path / "short.stl"
    bad.write_bytes(b" " * 80 + bytes([5, 0, 0, 0]))
    with pytest.raises(convexloc.ParseError, match="byte 80: the header announces 5 facets") as caught:
        convexloc.read_polyhedron(bad)
    assert str(caught.value).startswith(f"{bad}: byte 80: ")


def test_hulls_of_the_same_points_are_equal_in_any_order(tmp_path):
    # a cube's corners and its face centres: 8 vertices, 6 faces, one shape in every order
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float)
    centres = np.vstack([np.eye(3), -np.eye(3)])
    cloud = np.vstack([corners, centres])
    first = convexloc.Polyhedron.hull(cloud)
    assert first.vertex_count == 8 and first.face_count == 12
    rng = np.random.default_rng(5)
    for order in [cloud[::-1]] + [rng.permutation(cloud) for _ in range(20)]:
        other = convexloc.Polyhedron.hull(order)
        assert other == first and hash(other) == hash(first)
        np.testing.assert_array_equal(other.vertices, first.vertices)
        np.testing.assert_array_equal(other.triangles, first.triangles)
    # the same points as an .xyz scan with an intensity column, read as its hull
    scan = tmp_path / "scan.xyz"
    scan.write_text("".join(f"{x} {y} {z} 7\n" for x, y, z in rng.permutation(cloud)))
    assert convexloc.read_polyhedron(scan, hull=True) == first
