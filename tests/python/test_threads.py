"""Threads give the same answers, and a long batch lets other Python threads run."""

import threading
import time

import numpy as np
import pytest

import convexloc
from conftest import regular_polygon


@pytest.mark.parametrize("method", list(convexloc.LOCATORS_2D))
def test_threads_give_the_same_answers_2d(method):
    locator = convexloc.LOCATORS_2D[method](convexloc.Polygon(regular_polygon(257)))
    # enough points that every thread count below gets work (runs of 2^15 and more)
    points = np.random.default_rng(3).uniform(-1.2, 1.2, size=(1 << 18, 2))
    one = locator.locate(points, workers=1)
    for workers in (-1, 2, 3, 8):
        np.testing.assert_array_equal(locator.locate(points, workers=workers), one)
        np.testing.assert_array_equal(locator.locate_xy(*points.T, workers=workers), one)


@pytest.mark.parametrize("method", list(convexloc.LOCATORS_3D))
def test_threads_give_the_same_answers_3d(method):
    cloud = np.random.default_rng(4).normal(size=(300, 3))
    locator = convexloc.LOCATORS_3D[method](convexloc.Polyhedron.hull(cloud))
    points = np.random.default_rng(5).uniform(-3, 3, size=(1 << 17, 3))
    one = locator.locate(points, workers=1)
    for workers in (-1, 2, 4):
        np.testing.assert_array_equal(locator.locate(points, workers=workers), one)


def test_concurrent_calls_share_a_locator():
    locator = convexloc.PolarLocator(convexloc.Polygon(regular_polygon(1000)))
    points = np.random.default_rng(6).uniform(-1.2, 1.2, size=(1 << 16, 2))
    expected = locator.locate(points, workers=1)
    results = [None] * 4

    def work(k):
        results[k] = locator.locate(points, workers=1)

    workers = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    for r in results:
        np.testing.assert_array_equal(r, expected)


def ticks_during(call):
    """Runs call() while another Python thread records the time of each of its steps;
    returns the call's start and end and the recorded times."""
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())

    counter = threading.Thread(target=count)
    counter.start()
    time.sleep(0.02)  # let the counter run
    start = time.perf_counter()
    call()
    end = time.perf_counter()
    stop.set()
    counter.join()
    return start, end, np.array(ticks)


@pytest.mark.parametrize("build", [
    lambda: (convexloc.HalfplaneLocator(convexloc.Polygon(regular_polygon(2000))), 2),
    lambda: (convexloc.HalfspaceLocator(convexloc.Polyhedron.hull(
        np.random.default_rng(1).normal(size=(3000, 3)))), 3),
])
def test_gil_is_released_during_a_long_batch(build):
    """With the GIL held for the whole call, no step of the other thread could fall in the
    middle of it; released, that thread runs throughout."""
    locator, dims = build()
    points = np.random.default_rng(2).uniform(-1, 1, size=(1 << 17, dims))
    start, end, ticks = ticks_during(lambda: locator.locate(points, workers=1))
    duration = end - start
    assert duration > 0.05, "the batch is too short to tell"
    middle = ticks[(ticks > start + 0.25 * duration) & (ticks < end - 0.25 * duration)]
    assert len(middle) > 0
