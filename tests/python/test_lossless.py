"""Input is exact or refused: integers and long doubles that a double cannot hold exactly,
and masked arrays with masked elements, are errors naming the element, never rounded."""

import numpy as np
import pytest

import convexloc

BIG = 2**60


@pytest.fixture
def big_triangle():
    # (0, 0), (2^60, 0), (0, 2^60): every vertex is exactly a double
    return convexloc.Polygon(np.array([[0, 0], [BIG, 0], [0, BIG]], dtype=np.int64))


def test_integers_beyond_2_53_that_are_doubles_are_accepted(big_triangle):
    assert big_triangle.vertices.tolist() == [[0, 0], [BIG, 0], [0, BIG]]
    locator = convexloc.HalfplaneLocator(big_triangle)
    # (2^60 - 2^8, 2^8) is exactly a double pair and exactly on the hypotenuse
    on = np.array([[BIG - 256, 256]], dtype=np.int64)
    assert locator.locate(on).tolist() == [convexloc.BOUNDARY]


def test_the_point_one_below_2_60_is_refused(big_triangle):
    # (2^60 - 1, 1) lies exactly on the hypotenuse; rounded, it would be OUTSIDE
    for locator in (convexloc.HalfplaneLocator(big_triangle), convexloc.PolarLocator(big_triangle)):
        with pytest.raises(ValueError, match=r"points\[0, 0\] = 1152921504606846975 is not exactly"):
            locator.locate(np.array([[BIG - 1, 1]]))


@pytest.mark.parametrize("dtype, value", [
    (np.int64, 2**53 + 1), (np.int64, -(2**53) - 1), (np.int64, 2**63 - 1),
    (np.int64, -(2**63) + 1), (np.uint64, 2**64 - 1), (np.uint64, 2**53 + 1),
])
def test_inexact_integers_name_the_first_offender(dtype, value):
    points = np.zeros((4, 2), dtype=dtype)
    points[2, 1] = value
    points[3, 0] = value  # a later one: the first is named
    with pytest.raises(ValueError, match=rf"points\[2, 1\] = {value} is not exactly a float64"):
        convexloc.contains([[0, 0], [1, 0], [0, 1]], points)


@pytest.mark.parametrize("dtype, value", [
    (np.int64, 2**53), (np.int64, -(2**53)), (np.int64, -(2**63)), (np.uint64, 2**63),
    (np.int64, 2**62 + 2**10),
])
def test_exact_integers_are_accepted(dtype, value):
    points = np.array([[value, 0]], dtype=dtype)
    assert convexloc.contains([[0, 0], [1, 0], [0, 1]], points).tolist() == [False]


def test_columns_and_shapes_and_traces_are_checked(big_triangle):
    polar = convexloc.PolarLocator(big_triangle)
    x = np.array([[1, 2], [3, BIG + 1]], dtype=np.int64)
    with pytest.raises(ValueError, match=r"x\[1, 1\] = 1152921504606846977"):
        polar.locate_xy(x, np.zeros((2, 2)))
    with pytest.raises(ValueError, match=r"point\[0\] = 1152921504606846975"):
        polar.trace(np.array([BIG - 1, 1]))
    with pytest.raises(ValueError, match=r"vertices\[1, 0\] = 1152921504606846975"):
        convexloc.Polygon(np.array([[0, 0], [BIG - 1, 0], [0, 1]]))
    with pytest.raises(ValueError, match=r"points\[3, 2\] = 9007199254740993"):
        convexloc.Polyhedron.hull(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 2**53 + 1]]))


needs_longdouble = pytest.mark.skipif(
    np.finfo(np.longdouble).nmant <= np.finfo(np.float64).nmant,
    reason="long double is double on this platform")


@needs_longdouble
def test_long_double_off_by_2_pow_minus_62_is_refused():
    square = convexloc.Polygon([[0, 0], [1, 0], [1, 1], [0, 1]])
    x = np.longdouble(1) + np.longdouble(2) ** -62  # 2^-62 outside x = 1
    points = np.array([[0.5, 0.5], [x, 0.5]], dtype=np.longdouble)
    for cls in convexloc.LOCATORS_2D.values():
        with pytest.raises(ValueError, match=r"points\[1, 0\] = 1\.0000000000000000002 is not "
                                             r"exactly a float64 \(the nearest is 1\.0\)"):
            cls(square).locate(points)


@needs_longdouble
def test_long_doubles_that_are_doubles_are_accepted():
    square = convexloc.Polygon(np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=np.longdouble))
    points = np.array([[0.5, 0.5], [1.0, 0.25], [np.nan, 0], [np.inf, 0]], dtype=np.longdouble)
    assert convexloc.PolarLocator(square).locate(points).tolist() == [0, 1, 2, 2]
    big = np.array([[np.longdouble("1e4000"), 0]], dtype=np.longdouble)  # beyond the doubles' range
    with pytest.raises(ValueError, match=r"points\[0, 0\]"):
        convexloc.PolarLocator(square).locate(big)


def test_masked_arrays_with_masked_elements_are_refused():
    triangle = [[0, 0], [1, 0], [0, 1]]
    masked = np.ma.masked_array([[0.1, 0.1], [5, 5]], mask=[[0, 0], [1, 0]])
    with pytest.raises(TypeError, match=r"points: a masked array with masked elements"):
        convexloc.contains(triangle, masked)
    unmasked = np.ma.masked_array([[0.1, 0.1], [5, 5]], mask=False)
    assert convexloc.contains(triangle, unmasked).tolist() == [True, False]
