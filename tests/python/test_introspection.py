"""trace(), stats() and cells() as plain values; docstrings and stubs cover the API."""

import ast
import pathlib

import numpy as np
import pytest

import convexloc
from conftest import regular_polygon


def test_polar_cells_cover_the_edges():
    polygon = convexloc.Polygon(regular_polygon(12))
    polar = convexloc.PolarLocator(polygon, resolution=4)
    cells = polar.cells()
    stats = polar.stats()
    assert len(cells) == stats["cells"] == 8 * polar.slabs_per_octant == 32
    assert sum(len(c["edges"]) for c in cells) == stats["entries"]
    assert set(np.concatenate([c["edges"] for c in cells])) == set(range(12))
    for c in cells:
        assert c["outline"].shape[1] == 2 and c["outline"].dtype == np.float64
        assert 0 <= c["octant"] < 8
    assert sum(stats["histogram"]) == stats["cells"]
    assert len(polar.centre) == 2


@pytest.mark.parametrize("method", list(convexloc.LOCATORS_2D))
def test_2d_values_are_plain(method):
    locator = convexloc.LOCATORS_2D[method](convexloc.Polygon(regular_polygon(9)))
    trace = locator.trace((0.1, 0.2))
    assert trace["method"] == method == locator.method
    assert all(isinstance(e, tuple) and len(e) == 2 for e in trace["edges"])
    stats = locator.stats()
    assert stats["edges"] == 9 and stats["bytes"] > 0
    for cell in locator.cells():
        assert set(cell) == {"index", "octant", "outline", "dir_lo", "dir_hi", "hit_lo",
                             "hit_hi", "y0", "y1", "edges"}


@pytest.mark.parametrize("method", list(convexloc.LOCATORS_3D))
def test_3d_values_are_plain(method, cube):
    locator = convexloc.LOCATORS_3D[method](cube)
    trace = locator.trace((0.1, 0.2, 0.3))
    assert trace["method"] == method and trace["result"] == convexloc.INSIDE
    stats = locator.stats()
    assert stats["faces"] == 6 and stats["triangles"] == 12  # six squares, two triangles each
    cells = locator.cells()
    if method == "cubemap":
        assert len(cells) == stats["cells"] > 0
        assert locator.resolution == stats["resolution"]
        for c in cells[:50]:
            assert c["corners"].shape == (4, 3) and 0 <= c["cube_face"] < 6
    else:
        assert cells == []


def test_cubemap_trace_names_its_cell(cube):
    cubemap = convexloc.CubemapLocator(cube, resolution=4)
    trace = cubemap.trace((0.9, 0.1, 0.2))
    assert trace["cube_face"] == 0 and trace["level"] >= 0 and trace["centre"] is not None


def test_docstrings():
    assert "exact" in convexloc.__doc__
    for name in convexloc.__all__:
        value = getattr(convexloc, name)
        if callable(value):
            assert value.__doc__, name
    assert "O(1)" in convexloc.PolarLocator.__doc__
    assert "workers" in convexloc.PolarLocator.locate.__doc__
    assert "slabs per octant" in convexloc.PolarLocator.__init__.__doc__


def stub_names():
    """Top-level names and each class's members in the shipped __init__.pyi."""
    stub = pathlib.Path(convexloc.__file__).with_name("__init__.pyi")
    tree = ast.parse(stub.read_text())
    names, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names.add(node.name)
            own = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
            own |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
            own |= {t.id for n in node.body if isinstance(n, ast.Assign) for t in n.targets}
            for base in node.bases:
                if isinstance(base, ast.Subscript):  # a generic base: _Locator[...]
                    base = base.value
                if isinstance(base, ast.Name):
                    own |= members.get(base.id, set())
            members[node.name] = own
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
        elif isinstance(node, ast.FunctionDef):
            names.add(node.name)
        elif isinstance(node, ast.ImportFrom):  # re-exported: "from .types import X as X"
            names |= {a.asname for a in node.names if a.asname == a.name}
    return names, members


def test_stubs_cover_the_module():
    names, members = stub_names()
    assert set(convexloc.__all__) <= names
    for name in convexloc.__all__:
        value = getattr(convexloc, name)
        if isinstance(value, type) and not issubclass(value, (Exception, dict)):
            public = {m for m in dir(value) if not m.startswith("_")}
            if issubclass(value, int):  # an IntEnum: its own members, not int's methods
                public -= set(dir(int))
            assert public <= members[name], (name, public - members[name])


def test_the_typed_dicts_have_exactly_the_runtime_keys(square, cube):
    """convexloc.types (what the stubs re-export) names every key trace(), stats() and
    cells() return, and no other, for every method; the nested dicts too."""
    T = convexloc.types
    for cls in convexloc.LOCATORS_2D.values():
        locator = cls(square)
        trace = locator.trace((0.25, 0.75))
        assert set(trace) == set(T.Trace2D.__annotations__), cls.__name__
        assert set(trace["uniform"]) == set(T.UniformStep.__annotations__)
        assert set(trace["polar"]) == set(T.PolarStep.__annotations__)
        assert set(locator.stats()) == set(T.Stats2D.__annotations__), cls.__name__
        for cell in locator.cells():
            assert set(cell) == set(T.Cell2D.__annotations__), cls.__name__
    for cls in convexloc.LOCATORS_3D.values():
        locator = cls(cube)
        assert set(locator.trace((0.1, 0.2, 0.3))) == set(T.Trace3D.__annotations__), cls.__name__
        assert set(locator.stats()) == set(T.Stats3D.__annotations__), cls.__name__
        for cell in locator.cells():
            assert set(cell) == set(T.Cell3D.__annotations__), cls.__name__
    assert convexloc.CubemapLocator(cube).cells()  # the cell check above ran
