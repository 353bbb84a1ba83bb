"""Chunked input without Dask: a memory-mapped .npy, a text points file or any iterable of
arrays, located chunk by chunk in memory bounded by the chunk, with a progress callback."""

import tracemalloc

import numpy as np
import pytest

import convexloc
from conftest import LATTICE_OCTAGON, on_edges_lattice


@pytest.fixture
def octagon():
    return convexloc.Polygon(LATTICE_OCTAGON)


def lattice_points(count, seed=0):
    """Integer points on, in and around the octagon (every answer occurs)."""
    points = np.random.default_rng(seed).integers(-6, 14, size=(count, 2)).astype(float)
    edges = on_edges_lattice(LATTICE_OCTAGON)
    points[: len(edges)] = edges
    return points


def test_npy_file_is_memory_mapped_and_memory_stays_flat(tmp_path, octagon):
    points = lattice_points(1 << 20)  # 16 MiB of doubles
    np.save(tmp_path / "points.npy", points)
    expected = convexloc.PolarLocator(octagon).locate(points)
    del points
    out = np.lib.format.open_memmap(tmp_path / "codes.npy", mode="w+", dtype=np.int8,
                                    shape=(1 << 20,))
    seen = []
    tracemalloc.start()
    convexloc.locate_chunks(tmp_path / "points.npy", octagon, chunk=1 << 14, out=out,
                            progress=lambda done, total: seen.append((done, total)))
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 1 << 20, peak  # far below the 16 MiB of points: one chunk at a time
    np.testing.assert_array_equal(out, expected)
    assert seen[0] == (1 << 14, 1 << 20) and seen[-1] == (1 << 20, 1 << 20) and len(seen) == 64


def test_text_file(tmp_path, octagon):
    points = lattice_points(5000)
    lines = ["# x y"] + [f"{x!r} {y!r}" for x, y in points]
    lines.insert(100, "")
    (tmp_path / "points.txt").write_text("\n".join(lines) + "\n")
    seen = []
    codes = convexloc.locate_chunks(str(tmp_path / "points.txt"), convexloc.WedgeLocator(octagon),
                                    chunk=777, progress=lambda d, t: seen.append((d, t)))
    np.testing.assert_array_equal(codes, convexloc.WedgeLocator(octagon).locate(points))
    assert seen[-1] == (5000, None) and all(t is None for _, t in seen)


@pytest.mark.parametrize("text, line, problem", [
    ("0 0\n1 2 3\n", 2, "expected 2 numbers, got 3"),
    ("0 0\n\n# c\n1 x\n", 4, "not a number: 'x'"),
])
def test_text_file_errors_name_the_line(tmp_path, octagon, text, line, problem):
    path = tmp_path / "bad.txt"
    path.write_text(text)
    with pytest.raises(convexloc.ParseError) as caught:
        convexloc.locate_chunks(path, octagon, chunk=1)
    assert str(caught.value) == f"{path}:{line}: {problem}"
    assert (caught.value.path, caught.value.line, caught.value.problem) == (str(path), line, problem)


def test_any_iterable_of_arrays_and_3d(cube):
    rng = np.random.default_rng(4)
    parts = [rng.integers(-2, 3, size=(n, 3)) / 2 for n in (10, 0, 300, 1)]
    codes = list(convexloc.iter_locate(iter(parts), cube))
    assert [len(c) for c in codes] == [10, 0, 300, 1]
    cubemap = convexloc.CubemapLocator(cube)
    for got, part in zip(codes, parts):
        np.testing.assert_array_equal(got, cubemap.locate(part))
    whole = convexloc.locate_chunks((p.tolist() for p in parts), cubemap)
    np.testing.assert_array_equal(whole, cubemap.locate(np.concatenate(parts)))


def test_arguments_are_checked(octagon):
    points = lattice_points(100)[:10]
    with pytest.raises(ValueError, match="out has 5 elements, the source has more points"):
        convexloc.locate_chunks(points, octagon, chunk=4, out=np.zeros(5, dtype=np.int8))
    with pytest.raises(ValueError, match="out has 12 elements, the source has 10 points"):
        convexloc.locate_chunks(points, octagon, out=np.zeros(12, dtype=np.int8))
    with pytest.raises(ValueError, match="out must be a 1-D int8 array"):
        convexloc.locate_chunks(points, octagon, out=np.zeros(10))
    with pytest.raises(ValueError, match="chunk must be >= 1, got 0"):
        convexloc.locate_chunks(points, octagon, chunk=0)
    with pytest.raises(TypeError, match="locator must be a convexloc locator"):
        convexloc.locate_chunks(points, LATTICE_OCTAGON)
    with pytest.raises(ValueError, match=r"points must be an \(M, 2\) array"):
        convexloc.locate_chunks([np.zeros((3, 3))], octagon)
