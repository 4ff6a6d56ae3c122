#!/usr/bin/python3
"""A torus of 2·N² triangles as an OBJ with the defects of meshes as people have them, for timing
--repair: 1% of the faces flipped, 0.1% given twice, 1000 vertices in no face, and with UNWELDED 1
every triangle on its own three vertices (a soup to weld). N = 708 gives about 1M triangles.
Usage: defect_soup.py OUT.obj N UNWELDED(0|1)"""
import sys
import numpy as np


def main():
    out, n, unwelded = sys.argv[1], int(sys.argv[2]), sys.argv[3] == "1"
    rng = np.random.default_rng(1)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    u, v = 2 * np.pi * i / n, 2 * np.pi * j / n
    p = np.stack([(3 + np.cos(v)) * np.cos(u), (3 + np.cos(v)) * np.sin(u), np.sin(v)], -1).reshape(-1, 3)
    at = lambda a, b: (a % n) * n + b % n
    a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
    tris = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    flip = rng.random(len(tris)) < 0.01
    tris[flip] = tris[flip][:, ::-1]
    twice = tris[rng.random(len(tris)) < 0.001]
    tris = np.concatenate([tris, twice])
    if unwelded:
        p = p[tris.reshape(-1)]
        tris = np.arange(3 * len(tris)).reshape(-1, 3)
    p = np.concatenate([p, rng.random((1000, 3)) * 10 + 20])
    with open(out, "w") as f:
        np.savetxt(f, p, fmt="v %.9g %.9g %.9g")
        np.savetxt(f, tris + 1, fmt="f %d %d %d")
    print(out, len(p), "vertices,", len(tris), "faces,", int(flip.sum()), "flipped,", len(twice), "given twice")


if __name__ == "__main__":
    main()
