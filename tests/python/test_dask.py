"""convexloc.dask on a real distributed.LocalCluster with two worker processes: the same
answers as one local call, a worker killed in the middle of a run loses nothing, and each
worker builds the locator once, not once per chunk."""

import os
import sys
import time

import numpy as np
import pytest

import convexloc

dask = pytest.importorskip("dask", reason="python3-dask is not installed")
distributed = pytest.importorskip("distributed", reason="python3-distributed is not installed")
import cloudpickle  # noqa: E402  (distributed's own dependency)
import dask.array as da  # noqa: E402

import convexloc.dask as cldask  # noqa: E402
from conftest import LATTICE_OCTAGON, on_edges_lattice  # noqa: E402

# the workers cannot import this file: its functions travel by value
cloudpickle.register_pickle_by_value(sys.modules[__name__])

CHUNK = 4096

# tornado (under distributed) warns about its own event loop set-up
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")


def chunk_points(block_id=None, dims=2, delay=0.0):
    """Chunk i's points, the same wherever it is computed: lattice points on the octagon's
    edges and around it, in 2D, or on and around the unit cube in 3D."""
    if delay:
        time.sleep(delay)
    rng = np.random.default_rng(block_id[0])
    if dims == 2:
        edges = on_edges_lattice(LATTICE_OCTAGON)
        points = rng.integers(-6, 14, size=(CHUNK, 2)).astype(float)
        points[: len(edges)] = edges
        return points
    return rng.integers(-2, 3, size=(CHUNK, 3)).astype(float) / 2


def lazy_points(chunks, dims=2, delay=0.0):
    """An (chunks * CHUNK, dims) Dask array made chunk by chunk on the workers."""
    return da.map_blocks(chunk_points, dims=dims, delay=delay, chunks=((CHUNK,) * chunks, (dims,)),
                         dtype=float)


def local_points(chunks, dims=2):
    return np.concatenate([chunk_points((i, 0), dims) for i in range(chunks)])


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                       dashboard_address=None, silence_logs=40)
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


@pytest.fixture
def octagon():
    return convexloc.Polygon(LATTICE_OCTAGON)


def worker_counts(client, key):
    """{worker: (locators built, chunks located)} for one spec, read in the worker processes."""
    counts = client.run(cldask.build_counts)
    return {w: c.get(key, (0, 0)) for w, c in counts.items()}


def test_rows_equal_one_local_call(client, octagon):
    points = lazy_points(24)
    codes = cldask.locate(points, octagon)
    assert codes.dtype == np.int8 and codes.chunks == ((CHUNK,) * 24,)
    got = client.compute(codes).result()
    expected = convexloc.PolarLocator(octagon).locate(local_points(24))
    np.testing.assert_array_equal(got, expected)
    assert set(np.unique(got)) == {0, 1, 2}  # every answer occurs: a real test


def test_the_locator_is_built_once_per_worker(client):
    # a shape no other test uses, so its spec key is fresh in every worker
    shape = convexloc.Polygon(LATTICE_OCTAGON * 3)
    codes = cldask.locate(lazy_points(32), shape, "uniform")
    key = cldask.spec_of(shape, "uniform").key
    np.testing.assert_array_equal(client.compute(codes).result(),
                                  convexloc.UniformLocator(shape).locate(local_points(32)))
    counts = worker_counts(client, key)
    assert sum(chunks for _, chunks in counts.values()) == 32
    for built, chunks in counts.values():
        assert built == (1 if chunks else 0)
    assert sum(1 for _, chunks in counts.values() if chunks) >= 1


def test_columns_locator_and_dataframe(client, cube):
    cubemap = convexloc.CubemapLocator(cube, 3)
    points = lazy_points(6, dims=3)
    x, y, z = points[:, 0], points[:, 1], points[:, 2]
    expected = cubemap.locate(local_points(6, dims=3))
    np.testing.assert_array_equal(client.compute(cldask.locate((x, y, z), cubemap)).result(),
                                  expected)
    np.testing.assert_array_equal(client.compute(cldask.locate(points, cube)).result(), expected)
    dd = pytest.importorskip("dask.dataframe", reason="dask.dataframe needs pandas")
    frame = dd.from_dask_array(points, columns=["x", "y", "z"])
    series = cldask.locate_dataframe(frame, cube, "halfspace")
    got = client.compute(series).result()
    assert got.name == "location" and got.dtype == np.int8
    np.testing.assert_array_equal(got.to_numpy(), expected)


def test_a_worker_killed_mid_run_loses_nothing(client, octagon):
    before = set(client.scheduler_info()["workers"])
    points = lazy_points(60, delay=0.05)  # about 1.5 s on two workers
    future = client.compute(cldask.locate(points, octagon, "wedge"))
    deadline = time.monotonic() + 30
    while client.processing() == {} or sum(map(len, client.processing().values())) == 0:
        assert time.monotonic() < deadline
        time.sleep(0.01)
    time.sleep(0.3)  # some chunks done, most not
    assert not future.done()
    victim = sorted(before)[0]
    try:
        client.run(os._exit, 1, workers=[victim])
    except Exception:  # the connection dies with the process
        pass
    got = future.result(timeout=120)
    np.testing.assert_array_equal(got, convexloc.WedgeLocator(octagon).locate(local_points(60)))
    # the nanny started a new process in the victim's place
    client.wait_for_workers(2, timeout=60)
    assert set(client.scheduler_info()["workers"]) != before


def test_arguments_are_checked(octagon, cube):
    with pytest.raises(ValueError, match=r"points must be an \(M, 2\) array, got shape \(4, 3\)"):
        cldask.locate(da.zeros((4, 3)), octagon)
    with pytest.raises(ValueError, match="2 coordinate arrays given, the shape needs 3"):
        cldask.locate((da.zeros(3), da.zeros(3)), cube)
    with pytest.raises(ValueError, match="method must be one of halfplane, wedge"):
        cldask.locate(da.zeros((4, 2)), octagon, "cubemap")
    with pytest.raises(ValueError, match="method='wedge' given with a PolarLocator"):
        cldask.locate(da.zeros((4, 2)), convexloc.PolarLocator(octagon), "wedge")
    with pytest.raises(TypeError, match="must be a convexloc.Polygon, Polyhedron or locator"):
        cldask.locate(da.zeros((4, 2)), LATTICE_OCTAGON)
