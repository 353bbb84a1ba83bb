"""The array conversion rules: what locate() takes, what it refuses, and that it never crashes."""

import numpy as np
import pytest

import convexloc


@pytest.fixture
def polar(square):
    return convexloc.PolarLocator(square)


@pytest.fixture
def cubemap(cube):
    return convexloc.CubemapLocator(cube)


POINTS = np.array([[0.5, 0.5], [0.0, 0.5], [1.0, 1.0], [2.0, 0.5], [-1.0, -1.0], [0.25, 0.75]])
CODES = np.array([0, 1, 1, 2, 2, 0], dtype=np.int8)


def test_codes():
    assert (convexloc.INSIDE, convexloc.BOUNDARY, convexloc.OUTSIDE) == (0, 1, 2)
    assert convexloc.NAMES == ("inside", "boundary", "outside")


def test_float64_contiguous_is_read_in_place(polar):
    codes = polar.locate(POINTS)
    assert codes.dtype == np.int8 and codes.shape == (6,) and codes.flags.c_contiguous
    np.testing.assert_array_equal(codes, CODES)


@pytest.mark.parametrize("convert", [
    lambda p: p.tolist(),                                     # nested lists
    lambda p: [tuple(row) for row in p],                      # tuples
    lambda p: np.asfortranarray(p),                           # column-major
    lambda p: np.concatenate([p, p], axis=1)[:, ::2],         # strided columns
    lambda p: np.repeat(p, 3, axis=0)[::3],                   # strided rows
    lambda p: p.astype(np.float32),                           # float32 (exact here)
    lambda p: p.astype(">f8"),                                # big-endian
    lambda p: np.frombuffer(b"\0" + p.tobytes(), dtype=np.float64, count=p.size,
                            offset=1).reshape(p.shape),       # misaligned
])
def test_other_layouts_are_converted(polar, convert):
    np.testing.assert_array_equal(polar.locate(convert(POINTS)), CODES)


@pytest.mark.parametrize("dtype", [np.int8, np.int32, np.int64, np.uint16, np.uint64])
def test_integer_arrays_are_converted(dtype):
    locator = convexloc.HalfplaneLocator(convexloc.Polygon([[0, 0], [4, 0], [4, 4], [0, 4]]))
    points = np.array([[1, 1], [0, 2], [4, 4], [5, 1]], dtype=dtype)
    np.testing.assert_array_equal(locator.locate(points), [0, 1, 1, 2])


def test_read_only_and_views_are_accepted(polar):
    frozen = POINTS.copy()
    frozen.flags.writeable = False
    np.testing.assert_array_equal(polar.locate(frozen), CODES)
    np.testing.assert_array_equal(polar.locate(POINTS[2:4]), CODES[2:4])


def test_input_is_not_modified(polar):
    before = POINTS.copy()
    polar.locate(POINTS)
    np.testing.assert_array_equal(POINTS, before)


@pytest.mark.parametrize("empty", [np.zeros((0, 2)), [], np.zeros((0, 2), dtype=np.int32)])
def test_empty_gives_empty(polar, empty):
    codes = polar.locate(empty)
    assert codes.shape == (0,) and codes.dtype == np.int8


def test_empty_3d(cubemap):
    assert cubemap.locate(np.zeros((0, 3))).shape == (0,)
    assert cubemap.locate_xyz([], [], []).shape == (0,)


@pytest.mark.parametrize("bad, pattern", [
    (np.zeros((3, 3)), r"\(M, 2\) array, got shape \(3, 3\)"),
    (np.zeros((3,)), r"got shape \(3,\)"),
    (np.zeros((2,)), r"for one point pass \[\[\.\.\.\]\]"),
    (np.zeros((2, 2, 2)), r"got shape \(2, 2, 2\)"),
    (np.float64(1.0), r"got shape \(\)"),
    (3, r"got shape \(\)"),
    ([[1.0, 2.0], [3.0]], r"points: .*inhomogeneous"),
])
def test_wrong_shape_is_value_error(polar, bad, pattern):
    with pytest.raises(ValueError, match=pattern):
        polar.locate(bad)


@pytest.mark.parametrize("bad, pattern", [
    ("points", r"strings"),
    (np.array([["a", "b"]]), r"strings"),
    (np.array([[True, False]]), r"boolean"),
    (np.array([[1 + 2j, 0]]), r"complex"),
    ([[object(), 1.0]], r"points\[0, 0\] = <object object at .*> \(dtype object\)"),
    (None, r"Python objects"),
    ({"x": 1}, r"Python objects"),
])
def test_non_numeric_is_type_error(polar, bad, pattern):
    with pytest.raises(TypeError, match=pattern):
        polar.locate(bad)


def test_wrong_dimension_for_3d(cubemap):
    with pytest.raises(ValueError, match=r"\(M, 3\) array, got shape \(6, 2\)"):
        cubemap.locate(POINTS)


def test_nan_and_infinity_are_outside(polar, cubemap):
    odd = [np.nan, np.inf, -np.inf]
    points = np.array([[a, 0.5] for a in odd] + [[0.5, a] for a in odd] + [[np.nan, np.nan]])
    assert np.all(polar.locate(points) == convexloc.OUTSIDE)
    points3 = np.array([[a, 0, 0] for a in odd] + [[0, 0, a] for a in odd])
    assert np.all(cubemap.locate(points3) == convexloc.OUTSIDE)
    assert polar.trace([np.nan, 0.5])["result"] == convexloc.OUTSIDE
    assert cubemap.trace([0, np.inf, 0])["non_finite"]


def test_locate_xy_shapes(polar):
    x = POINTS[:, 0].reshape(2, 3)
    y = POINTS[:, 1].reshape(2, 3)
    codes = polar.locate_xy(x, y)
    assert codes.shape == (2, 3)
    np.testing.assert_array_equal(codes.ravel(), CODES)
    assert polar.locate_xy(0.5, 0.5).shape == ()
    assert int(polar.locate_xy(0.5, 1.0)) == convexloc.BOUNDARY
    np.testing.assert_array_equal(polar.locate_xy(list(POINTS[:, 0]), POINTS[:, 1].astype(np.float32)),
                                  CODES)
    with pytest.raises(ValueError, match=r"do not broadcast together: x \(6,\), y \(5,\)"):
        polar.locate_xy(POINTS[:, 0], POINTS[:5, 1])
    with pytest.raises(TypeError, match="y must be numbers"):
        polar.locate_xy(POINTS[:, 0], ["a"] * 6)


def test_locate_xyz(cubemap):
    x, y, z = np.array([[0.0, 0, 0], [1, 0, 0], [2, 0, 0]]).T
    np.testing.assert_array_equal(cubemap.locate_xyz(x, y, z), [0, 1, 2])


def test_workers_argument(polar):
    for workers in (1, 3, -1, -2, -4096):
        np.testing.assert_array_equal(polar.locate(POINTS, workers=workers), CODES)
    with pytest.raises(ValueError, match="workers must be a thread count .* not 0"):
        polar.locate(POINTS, workers=0)
    with pytest.raises(ValueError, match=r"workers must be .*, got 4611686018427387904"):
        polar.locate(POINTS, workers=2**62)
    with pytest.raises(ValueError, match=r"workers must be .*, got -1180591620717411303424"):
        polar.locate_xy(POINTS[:, 0], POINTS[:, 1], workers=-(2**70))
    with pytest.raises(TypeError, match="workers must be an integer, got 2.5"):
        polar.locate(POINTS, workers=2.5)
    with pytest.raises(TypeError):
        polar.locate(POINTS, 2)  # workers is keyword-only


def test_threads_is_the_deprecated_name_of_workers(polar):
    with pytest.warns(DeprecationWarning, match="threads= is now workers="):
        np.testing.assert_array_equal(polar.locate(POINTS, threads=3), CODES)
    with pytest.warns(DeprecationWarning):
        np.testing.assert_array_equal(polar.locate(POINTS, threads=0), CODES)
    with pytest.raises(ValueError, match="threads must be from 0 .* got -1"):
        with pytest.warns(DeprecationWarning):
            polar.locate(POINTS, threads=-1)
    with pytest.raises(TypeError, match="not both"):
        polar.locate(POINTS, workers=2, threads=2)


def test_trace_point_shape(polar, cubemap):
    assert polar.trace((0.5, 0.5))["result"] == convexloc.INSIDE
    assert polar.trace(np.array([1, 1]))["result"] == convexloc.BOUNDARY
    with pytest.raises(ValueError, match=r"point must be 2 numbers, got shape \(3,\)"):
        polar.trace([1, 2, 3])
    with pytest.raises(ValueError, match=r"point must be 3 numbers"):
        cubemap.trace([[0, 0, 0]])
    with pytest.raises(TypeError):
        polar.trace(["a", "b"])


def test_conveniences_validate(square):
    with pytest.raises(ValueError, match="polygon must be an"):
        convexloc.contains([1, 2, 3], [[0, 0]])
    with pytest.raises(ValueError, match="points must be an"):
        convexloc.contains(square, [[0, 0, 0]])
    with pytest.raises(ValueError, match="cloud must be an"):
        convexloc.hull_contains([[0, 0]], [[0, 0, 0]])
    assert convexloc.contains(square, np.zeros((0, 2))).dtype == np.bool_


def explicit(locator, *columns):
    """What the columns should give: locate() on the explicitly broadcast points."""
    arrays = np.broadcast_arrays(*[np.asarray(c, dtype=float) for c in columns])
    rows = np.stack([a.ravel() for a in arrays], axis=1)
    return locator.locate(rows).reshape(arrays[0].shape)


@pytest.mark.parametrize("x, y", [
    (np.linspace(-0.5, 1.5, 3)[:, None], np.linspace(-0.5, 1.5, 4)[None, :]),   # (3,1) x (1,4)
    (np.linspace(-0.5, 1.5, 9), 0.5),                                           # a scalar
    (np.arange(24.0).reshape(2, 3, 4) / 10, np.arange(4.0)[::-1] / 3),         # (2,3,4) x (4,)
    (np.arange(24.0).reshape(2, 3, 4).transpose(2, 0, 1) / 10, 1.0),            # transposed
    (np.arange(60.0).reshape(6, 10)[::2, ::3] / 20, np.zeros((1, 1, 4))),       # strided views
    (np.arange(-8, 8)[::-1] / 8, np.arange(-8, 8) / 8),                         # negative stride
    (np.zeros((0, 1)), np.zeros((1, 5))),                                       # empty result
])
def test_locate_xy_broadcasts_like_a_ufunc(polar, x, y):
    codes = polar.locate_xy(x, y)
    expected = explicit(polar, x, y)
    assert codes.shape == expected.shape and codes.dtype == np.int8
    np.testing.assert_array_equal(codes, expected)


def test_locate_xyz_broadcasts_and_reads_views(cubemap):
    rng = np.random.default_rng(3)
    rows = rng.integers(-2, 3, size=(5000, 3)) / 2
    np.testing.assert_array_equal(cubemap.locate_xyz(rows[:, 0], rows[:, 1], rows[:, 2]),
                                  cubemap.locate(rows))
    grid = [np.linspace(-1.5, 1.5, 7).reshape(shape) for shape in ((7, 1, 1), (1, 7, 1), (1, 1, 7))]
    codes = cubemap.locate_xyz(*grid)
    assert codes.shape == (7, 7, 7)
    np.testing.assert_array_equal(codes, explicit(cubemap, *grid))
    assert set(np.unique(codes)) == {0, 1, 2}


def test_locate_xy_on_many_threads_equals_one(polar):
    rng = np.random.default_rng(8)
    x = rng.integers(-2, 4, size=(300, 1)) / 2
    y = rng.integers(-2, 4, size=(1, 700)) / 2
    one = polar.locate_xy(x, y, workers=1)
    np.testing.assert_array_equal(polar.locate_xy(x, y, workers=3), one)
    np.testing.assert_array_equal(one, explicit(polar, x, y))
