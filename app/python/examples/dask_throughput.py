"""Throughput of convexloc.dask against one process, on points generated chunk by chunk
(never all in memory), with an optional worker killed in the middle of the run.

    PYTHONPATH=build/python /usr/bin/python3 app/python/examples/dask_throughput.py \
        --points 100000000 --workers 2 --kill

Both runs classify the same points (chunk i is made from seed i) against a 1024-gon (or,
with --3d, a 10^4-face hull) and reduce each chunk to its counts of INSIDE, BOUNDARY and
OUTSIDE and an order-sensitive checksum of its codes; the totals must agree exactly. The one-process run makes and locates the chunks in
a loop; the Dask run does the same on a distributed.LocalCluster of worker processes with
one thread each.
"""

import argparse
import os
import threading
import time
from typing import Union

import numpy as np
import numpy.typing as npt

import convexloc
import convexloc.dask


Counts = npt.NDArray[np.int64]


def chunk(seed: int, size: int, dims: int) -> npt.NDArray[np.float64]:
    """Chunk `seed`'s points: uniform in [-1.2, 1.2]^dims."""
    return np.random.default_rng(seed).uniform(-1.2, 1.2, size=(size, dims))


def counts_of(codes: npt.NDArray[np.int8]) -> Counts:
    """INSIDE, BOUNDARY, OUTSIDE counts of a chunk's answers and sum(i * code[i]), an
    order-sensitive check, as a (1, 4) array."""
    check = np.dot(np.arange(len(codes), dtype=np.int64), codes.astype(np.int64))
    return np.append(np.bincount(codes, minlength=3), check)[None, :]


def make_shape(dims: int) -> Union[convexloc.Polygon, convexloc.Polyhedron]:
    if dims == 2:
        t = 2 * np.pi * np.arange(1024) / 1024
        return convexloc.Polygon(np.column_stack([np.cos(t), np.sin(t)]))
    rng = np.random.default_rng(1)
    cloud = rng.normal(size=(5002, 3))
    return convexloc.Polyhedron.hull(cloud / np.linalg.norm(cloud, axis=1)[:, None])


def one_process(shape: Union[convexloc.Polygon, convexloc.Polyhedron], chunks: int, size: int,
                dims: int) -> Counts:
    locator: Union[convexloc.PolarLocator, convexloc.CubemapLocator]
    if isinstance(shape, convexloc.Polygon):
        locator = convexloc.PolarLocator(shape)
    else:
        locator = convexloc.CubemapLocator(shape)
    total = np.zeros(4, dtype=np.int64)
    for i in range(chunks):
        total += counts_of(locator.locate(chunk(i, size, dims), workers=1))[0]
    return total


def with_dask(shape: Union[convexloc.Polygon, convexloc.Polyhedron], chunks: int, size: int,
              dims: int, workers: int, kill: float) -> tuple[Counts, float]:
    import dask.array as da
    import distributed

    cluster = distributed.LocalCluster(n_workers=workers, processes=True, threads_per_worker=1,
                                       dashboard_address=None, silence_logs=40)
    client = distributed.Client(cluster)
    points = da.map_blocks(lambda block_id=None: chunk(block_id[0], size, dims),
                           chunks=((size,) * chunks, (dims,)), dtype=float)
    codes = convexloc.dask.locate(points, shape)
    counts = codes.map_blocks(counts_of, chunks=((1,) * chunks, (4,)), new_axis=1,
                              dtype=np.int64)
    start = time.perf_counter()
    future = client.compute(counts.sum(axis=0))
    if kill:
        victim = sorted(client.scheduler_info()["workers"])[0]

        def shoot() -> None:
            time.sleep(kill)
            try:
                client.run(os._exit, 1, workers=[victim])
            except Exception:
                pass
            print(f"killed worker {victim} at {kill} s")

        threading.Thread(target=shoot, daemon=True).start()
    total = future.result()
    seconds = time.perf_counter() - start
    client.close()
    cluster.close()
    return total, seconds


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=10**8)
    parser.add_argument("--chunk", type=int, default=2**20)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--kill", type=float, default=0.0,
                        help="kill one worker this many seconds into the Dask run")
    parser.add_argument("--3d", dest="dims", action="store_const", const=3, default=2)
    args = parser.parse_args()
    chunks = -(-args.points // args.chunk)
    n = chunks * args.chunk
    shape = make_shape(args.dims)
    start = time.perf_counter()
    local = one_process(shape, chunks, args.chunk, args.dims)
    local_s = time.perf_counter() - start
    total, dask_s = with_dask(shape, chunks, args.chunk, args.dims, args.workers, args.kill)
    print(f"{n:,} points in {chunks} chunks of {args.chunk:,}, {args.dims}D")
    print(f"one process:        {local_s:8.1f} s  {n / local_s / 1e6:7.1f} M points/s  {local}")
    print(f"dask, {args.workers} workers:    {dask_s:8.1f} s  {n / dask_s / 1e6:7.1f} M points/s  "
          f"{total}")
    print("same counts:", bool(np.array_equal(local, total)))
    return 0 if np.array_equal(local, total) else 1


if __name__ == "__main__":
    raise SystemExit(main())
