#!/usr/bin/env python3
"""Scale out with Dask: the deviation of a large point scan from a surface, and the meshing of a
list of files, spread over the worker processes of a Dask cluster.

The surface's locator is pickled and sent to every worker once (``Client.scatter(...,
broadcast=True)``); the scan is cut into blocks that are mapped over the workers, each answering
its block's closest points with the C library; the files are mapped one task per file. The
results are gathered and compared, byte for byte, with the same work done in this process.

Needs numpy and Dask (Debian: python3-dask, python3-distributed); the bezsurf package itself
does not. Run with the library on the search path, or with
BEZSURF_LIBRARY=build/lib/libbezsurf.so.1 PYTHONPATH=bindings/python python3 examples/python/dask_scale.py
"""

import argparse
import hashlib
import pathlib
import sys
import time
from typing import List, Tuple

import numpy as np

import bezsurf

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]


def scan(count: int, seed: int) -> np.ndarray:
    """A synthetic scan: points on the teapot's surface moved off it by up to 5% of its size."""
    teapot = bezsurf.Surface.builtin("teapot")
    rng = np.random.default_rng(seed)
    patch = rng.integers(0, len(teapot), count)
    u, v = rng.random(count), rng.random(count)
    points = np.empty((count, 3))
    for p in range(len(teapot)):
        mine = patch == p
        points[mine] = teapot[p].eval(u[mine], v[mine])
    return points + rng.normal(scale=0.05 * 3.2 / 3, size=points.shape)  # the pot is ~3.2 wide


def deviation(locator: bezsurf.Locator, block: np.ndarray) -> np.ndarray:
    """Distances of a block of points from the locator's surface (one task)."""
    return locator.closest_point(block).dist


def mesh_digest(path: str, tolerance: float) -> Tuple[str, int, str]:
    """Mesh one file to a relative tolerance: its name, triangle count and a digest of the
    mesh's vertex positions and triangles (one task)."""
    mesh = bezsurf.Surface.load(path).tessellate_adaptive(tolerance, relative=True, subdivide=True)
    digest = hashlib.sha256(mesh.positions().tobytes() + mesh.triangles().tobytes()).hexdigest()
    return pathlib.Path(path).name, mesh.triangle_count, digest


def parts() -> List[str]:
    """The files to mesh: the tea set shipped in data/."""
    return sorted(str(p) for p in (SOURCE_DIR / "data").glob("*.bpt"))


def on_cluster(locator: bezsurf.Locator, points: np.ndarray, files: List[str], blocks: int,
               workers: int, tolerance: float) -> Tuple[np.ndarray, list, float]:
    from dask.distributed import Client, LocalCluster  # an optional extra, like numpy
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        start = time.perf_counter()
        shared = client.scatter(locator, broadcast=True)  # pickled once, sent to every worker
        pieces = client.scatter(np.array_split(points, blocks))
        dist = np.concatenate(client.gather(client.map(deviation, [shared] * blocks, pieces)))
        meshes = client.gather(client.map(mesh_digest, files, [tolerance] * len(files)))
        return dist, meshes, time.perf_counter() - start


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=400_000, help="points in the scan")
    parser.add_argument("--blocks", type=int, default=16, help="blocks the scan is cut into")
    parser.add_argument("--workers", type=int, default=2, help="worker processes")
    parser.add_argument("--tolerance", type=float, default=1e-4, help="relative mesh tolerance")
    args = parser.parse_args()

    points = scan(args.points, seed=7)
    locator = bezsurf.Locator(bezsurf.Surface.builtin("teapot"))
    files = parts()

    start = time.perf_counter()
    dist = deviation(locator, points)
    meshes = [mesh_digest(f, args.tolerance) for f in files]
    alone = time.perf_counter() - start

    dist_c, meshes_c, spread = on_cluster(locator, points, files, args.blocks, args.workers,
                                          args.tolerance)
    same = dist_c.tobytes() == dist.tobytes() and meshes_c == meshes
    print(f"scan of {args.points} points: deviation max {dist.max():.6f}, "
          f"mean {dist.mean():.6f}")
    for name, triangles, digest in meshes:
        print(f"{name}: {triangles} triangles, {digest[:16]}")
    print(f"one process {alone:.2f} s, {args.workers} workers {spread:.2f} s "
          f"(speed-up {alone / spread:.2f}x); results {'identical' if same else 'DIFFER'}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
