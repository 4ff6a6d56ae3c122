"""Gaussians inferred from a plain mesh (GPS paper Eq. 16-17), as in the paper's inference demo: a
polygon mesh without covariances gets one Gaussian per vertex from the faces around it, and its GPS
limit surface keeps the mesh's corners and edges where plain subdivision rounds them off.

Shown on a box of quads built here from arrays: the limit points of its corners lie far nearer to the
input with inferred Gaussians than with equal isotropic ones (plain Catmull-Clark). Along the edges
the inferred Gaussians pull the surface toward the corners, so there it is not nearer everywhere:
what fitting the Gaussians to a shape, rather than inferring them, is for.
"""
import numpy as np

import gpsurf


def box(n):
    """The surface of the unit cube as an n x n grid of quads on each side."""
    index, positions, faces = {}, [], []

    def vertex(p):
        if p not in index:
            index[p] = len(positions)
            positions.append(np.array(p, dtype=float) / n)
        return index[p]

    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, n):
            for i in range(n):
                for j in range(n):
                    quad = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0, 0, 0]
                        p[axis], p[u], p[v] = side, i + di, j + dj
                        quad.append(vertex(tuple(p)))
                    faces.append(quad if side == n else quad[::-1])  # outward normals
    return np.array(positions), faces


positions, faces = box(4)
inferred = gpsurf.Mesh(positions, faces)  # covariances inferred, bias 0.05
isotropic = gpsurf.Mesh(positions, faces, covariances=np.repeat(0.01 * np.eye(3)[None], len(positions), axis=0))
# Vertices on the box's edges and corners: two or three coordinates at 0 or 1.
on_faces = np.sum((positions == 0) | (positions == 1), axis=1)
features = {"corners": on_faces == 3, "edges": on_faces == 2}

distances = {}
for label, mesh in (("inferred", inferred), ("isotropic", isotropic)):
    limit = gpsurf.subdivide(mesh, levels=0, limit=True).positions
    distances[label] = np.linalg.norm(limit - positions, axis=1)
print(f"{len(positions)} vertices, {len(faces)} quads; distance from each vertex to its limit point:")
for feature, chosen in features.items():
    print(f"  {feature:8} max: inferred {distances['inferred'][chosen].max():.5f}, "
          f"isotropic (plain Catmull-Clark) {distances['isotropic'][chosen].max():.5f}")
corners = features["corners"]
assert distances["inferred"][corners].max() < 0.25 * distances["isotropic"][corners].max()

points, normals, triangles = gpsurf.tessellate(inferred, level=8)
print(f"tessellated the inferred surface: {len(points)} points, {len(triangles)} triangles")
print("ok: inferred Gaussians keep the box's corners")
