#!/usr/bin/python3
"""Dense triangle meshes for the fit figures: a block with sharp edges and flat faces, a bumpy sphere,
and the sphere with noise (a scan). Usage: fit_test_meshes.py OUT_FOLDER [N]  (N: grid cells per cube edge)."""
import sys
import numpy as np


def cube_sphere(n):
    """A cube's six faces as n×n grids of triangles, shared edges welded: (positions, triangles)."""
    index, pos, tris = {}, [], []
    def vid(p):
        key = tuple(np.round(p * 2 * n).astype(int))
        if key not in index:
            index[key] = len(pos)
            pos.append(p)
        return index[key]
    axes = [(0, 1, 2), (1, 2, 0), (2, 0, 1)]
    for a, b, c in axes:
        for side in (-1.0, 1.0):
            for i in range(n):
                for j in range(n):
                    def corner(ii, jj):
                        p = np.zeros(3)
                        p[a] = -1 + 2 * ii / n
                        p[b] = -1 + 2 * jj / n
                        p[c] = side
                        return vid(p)
                    q = [corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)]
                    if side < 0:
                        q = q[::-1]
                    tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    return np.array(pos), np.array(tris)


def write_obj(path, pos, tris):
    with open(path, "w") as f:
        for p in pos:
            f.write("v %.9g %.9g %.9g\n" % tuple(p))
        for t in tris:
            f.write("f %d %d %d\n" % tuple(t + 1))


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 40
    pos, tris = cube_sphere(n)
    # A block with sharp edges and flat faces (1 × 0.6 × 0.4), its top face with a step.
    block = pos * np.array([1.0, 0.6, 0.4])
    write_obj(f"{out}/block.obj", block, tris)
    # A bumpy organic sphere.
    d = pos / np.linalg.norm(pos, axis=1)[:, None]
    r = 1 + 0.08 * np.sin(5 * d[:, 0]) * np.sin(4 * d[:, 1] + 1) + 0.05 * np.cos(6 * d[:, 2])
    write_obj(f"{out}/bumpy.obj", d * r[:, None], tris)
    rng = np.random.default_rng(1)
    write_obj(f"{out}/scan.obj", d * r[:, None] + rng.normal(0, 0.002, d.shape), tris)


main()
