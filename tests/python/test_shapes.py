"""Polygon, Polyhedron, the readers, and errors with the command-line tool's messages."""

import subprocess

import numpy as np
import pytest

import convexloc
from conftest import env_path, write_polygon


def test_polygon_normalises():
    clockwise = [[0, 0], [0, 1], [1, 1], [1, 0.5], [1, 0]]  # clockwise, a collinear vertex
    p = convexloc.Polygon(clockwise)
    assert len(p) == 4 and p.was_clockwise and p.dropped_count == 1
    assert p.vertices.shape == (4, 2) and p.vertices.dtype == np.float64
    assert p.bounds == (0.0, 0.0, 1.0, 1.0)  # Shapely's order
    assert p.area == pytest.approx(1.0)
    assert p.source_index.dtype == np.int64
    assert "4 vertices" in repr(p)


@pytest.mark.parametrize("vertices, pattern", [
    ([[0, 0], [1, 0], [1, 1], [0.5, 0.2], [0, 1]], "not convex"),
    ([[0, 0], [1, 1], [2, 2]], "collinear"),
    ([[0, 0], [1, 0], [np.nan, 1]], ""),
    ([[0, 0], [1, 0]], ""),
])
def test_polygon_errors(vertices, pattern):
    with pytest.raises(convexloc.GeometryError, match=pattern) as caught:
        convexloc.Polygon(vertices)
    assert isinstance(caught.value, ValueError)
    assert caught.value.path is None


def test_polygon_bad_arrays():
    with pytest.raises(ValueError, match=r"vertices must be an \(M, 2\) array"):
        convexloc.Polygon([[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    with pytest.raises(TypeError, match="vertices must be numbers"):
        convexloc.Polygon("square")


def test_polyhedron_from_faces():
    v = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    quads = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    for faces in (quads, np.array(quads), np.array(quads, dtype=np.uint32),
                  [tuple(f) for f in quads]):
        box = convexloc.Polyhedron(v, faces)
        assert box.face_count == 12 and box.vertex_count == 8
        assert box.volume == pytest.approx(1.0) and box.area == pytest.approx(6.0)
        assert box.triangles.shape == (12, 3) and box.neighbours.shape == (12, 3)
        assert box.bounds == (0.0, 0.0, 0.0, 1.0, 1.0, 1.0)
        assert len(box.centre) == 3
    # mixed face sizes: a ragged list
    pyramid = convexloc.Polyhedron([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1]],
                                   [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
    assert pyramid.face_count == 6


def test_polyhedron_errors():
    tetra = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    with pytest.raises(convexloc.GeometryError, match="open"):
        convexloc.Polyhedron(tetra, [[0, 2, 1], [0, 1, 3], [0, 3, 2]])
    # a negative index and one past the end are the same problem, the same exception
    with pytest.raises(convexloc.GeometryError,
                       match=r"^face 1 refers to vertex -1, but the vertices are 0 to 3$"):
        convexloc.Polyhedron(tetra, [[0, 2, 1], [0, 1, -1]])
    with pytest.raises(convexloc.GeometryError,
                       match=r"^face 0 refers to vertex -2, but the vertices are 0 to 3$"):
        convexloc.Polyhedron(tetra, np.array([[0, 2, -2]]))
    with pytest.raises(convexloc.GeometryError,
                       match=r"^face 1 refers to vertex 4, but the vertices are 0 to 3$"):
        convexloc.Polyhedron(tetra, [[0, 2, 1], [0, 1, 4]])
    with pytest.raises(convexloc.GeometryError, match=r"face 1 refers to vertex 2361183241434822606848,"):
        convexloc.Polyhedron(tetra, [[0, 2, 1], [0, 1, 2**71]])
    with pytest.raises(convexloc.GeometryError):
        convexloc.Polyhedron(tetra, [[0, 2, 1], [0, 1, 7], [0, 3, 2], [1, 2, 3]])
    with pytest.raises(TypeError, match="not a vertex index"):
        convexloc.Polyhedron(tetra, [[0, 2, 1.5]])
    with pytest.raises(TypeError, match="not a vertex index"):
        convexloc.Polyhedron(tetra, [[0, 2, 1], [0, 1]] + [["a", "b", "c"]])


def test_hull():
    rng = np.random.default_rng(1)
    cloud = rng.normal(size=(200, 3))
    hull = convexloc.Polyhedron.hull(cloud)
    assert hull.face_count >= 4
    locator = convexloc.HalfspaceLocator(hull)
    assert np.all(locator.locate(cloud) != convexloc.OUTSIDE)
    with pytest.raises(convexloc.GeometryError):
        convexloc.Polyhedron.hull(np.zeros((10, 3)))
    with pytest.raises(convexloc.GeometryError):
        convexloc.Polyhedron.hull([[0, 0, 0], [1, 0, 0], [0, 1, 0]])


def test_read_polygon_and_polyhedron(tmp_path):
    assets = env_path("CONVEXLOC_ASSETS")
    hexagon = convexloc.read_polygon(assets / "hexagon.txt")
    assert len(hexagon) == 6
    assert convexloc.read_polygon(str(assets / "hexagon.txt")).bounds == hexagon.bounds
    cube = convexloc.read_polyhedron(assets / "cube.off")
    assert cube.face_count == 12
    assert convexloc.read_polyhedron(assets / "icosahedron.obj").face_count == 20


def test_file_errors_carry_the_line(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0\n1 0\n# a comment\n1 x\n")
    with pytest.raises(convexloc.ParseError) as caught:
        convexloc.read_polygon(bad)
    e = caught.value
    assert str(e) == f"{bad}:4: not a number: 'x'"
    assert (e.path, e.line, e.problem) == (str(bad), 4, "not a number: 'x'")
    reflex = write_polygon(tmp_path / "reflex.txt", [[0, 0], [1, 0], [1, 1], [0.5, 0.2], [0, 1]])
    with pytest.raises(convexloc.GeometryError, match=r"reflex\.txt:4: not convex") as caught:
        convexloc.read_polygon(reflex)
    assert caught.value.line == 4
    empty = tmp_path / "empty.txt"
    empty.write_text("# nothing\n")
    with pytest.raises(convexloc.ParseError, match="empty.txt: no vertices"):
        convexloc.read_polygon(empty)
    with pytest.raises(convexloc.FileError, match="cannot open: No such file") as caught:
        convexloc.read_polygon(tmp_path / "missing.txt")
    assert isinstance(caught.value, OSError) and isinstance(caught.value, convexloc.Error)
    with pytest.raises(convexloc.FileError, match="cannot open: it is a directory"):
        convexloc.read_polyhedron(tmp_path)
    with pytest.raises(convexloc.UsageError) as caught:
        convexloc.read_polyhedron(tmp_path / "shape.3mf")
    assert caught.value.path is None


def test_mesh_errors_carry_the_line():
    data = env_path("CONVEXLOC_TEST_DATA")
    with pytest.raises(convexloc.ParseError) as caught:
        convexloc.read_polyhedron(data / "bad_face.obj")
    assert caught.value.line == 6
    assert str(caught.value).startswith(f"{data / 'bad_face.obj'}:6: ")


def cli_message(program, path):
    """What `convexloc info PATH` prints on stderr, and its exit code."""
    run = subprocess.run([str(program), "info", str(path)], capture_output=True, text=True)
    return run.returncode, run.stderr.strip()


def test_messages_equal_the_cli(tmp_path):
    """Every file of tests/data: the module fails where the tool fails, with its message."""
    program = env_path("CONVEXLOC_BIN")
    data = env_path("CONVEXLOC_TEST_DATA")
    files = sorted(p for p in data.iterdir() if p.suffix in (".txt", ".off", ".obj"))
    files += [tmp_path / "missing.off", tmp_path / "missing.txt"]
    compared = 0
    for path in files:
        read = convexloc.read_polyhedron if path.suffix in (".off", ".obj") else convexloc.read_polygon
        code, message = cli_message(program, path)
        if code == 0:
            read(path)
            continue
        with pytest.raises(convexloc.Error) as caught:
            read(path)
        assert str(caught.value) == message, path
        compared += 1
    assert compared >= 20


def test_a_non_planar_face_is_named_once():
    # a square base lifted at one corner, folding inward: the error names the face once, the
    # corner off the plane and by how much, not a diagonal the input does not have
    vertices = [[0, 0, 0], [1, 0, 0], [1, 1, 0.1], [0, 1, 0], [0.5, 0.5, 1]]
    faces = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4], [0, 3, 2, 1]]
    with pytest.raises(convexloc.GeometryError) as caught:
        convexloc.Polyhedron(vertices, faces)
    message = str(caught.value)
    assert message.startswith("face 4 is not planar: vertex ")
    assert "off the plane" in message and "hull=True" in message
    assert "face 4 and face 4" not in message and message.count("face 4") == 1
