"""geometry-central's flipOut (Sharp & Crane 2020, "You Can Find Geodesic Paths in Triangle Meshes
by Just Flipping Edges") through potpourri3d, for the "surface at scale" benchmark only
(bench/surface-scale.mjs runs it; never a test dependency). Install it into a venv under build/:

    python3 -m venv build/pyenv && build/pyenv/bin/pip install potpourri3d

usage: python flipout.py <mesh.obj>   with {"pairs": [[a, b], ...]} (file vertex indices) on stdin.
Prints {"construct_ms": .., "ms": [...], "lengths": [...]}: per pair, the time of
find_geodesic_path (native, one thread) and the length of the path it returns.
"""
import json
import sys
import time

import numpy as np
import potpourri3d as pp3d


def main():
    vertices, faces = pp3d.read_mesh(sys.argv[1])
    pairs = json.load(sys.stdin)["pairs"]
    t0 = time.perf_counter()
    solver = pp3d.EdgeFlipGeodesicSolver(vertices, faces)
    construct_ms = 1000 * (time.perf_counter() - t0)
    ms, lengths = [], []
    for a, b in pairs:
        t0 = time.perf_counter()
        path = solver.find_geodesic_path(v_start=int(a), v_end=int(b))
        ms.append(1000 * (time.perf_counter() - t0))
        lengths.append(float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum()))
    json.dump({"construct_ms": construct_ms, "ms": ms, "lengths": lengths}, sys.stdout)


if __name__ == "__main__":
    main()
