"""Preiner's cones, the demo of the GPS paper's Python code (gps-py, py/cones.py; the paper's figure of
cones): one apex Gaussian over a ring of eight, Σ = 0.01·I at the ring, and gps-py's five apex
covariances. gps-py subdivides five times with libigl's Loop (Warren's weights), without the limit;
gpsurf does the same (scheme "loop", loop_beta "warren", limit=False), and this script checks it at
every base vertex against an independent numpy re-implementation of gps-py's loop_gps. It then
gives the apex height of each cone's limit surface: a small apex covariance pulls the surface up to
the control point (y = 1.5), an anisotropic one makes a concave tip, a plateau or a cylinder.
"""
import numpy as np

import gpsurf

LEVELS = 5
# gps-py's apex covariances, in its order (py/cones.py).
APEX = {
    "plain": 0.01 * np.eye(3),
    "pointy": 0.01 * 0.001 * np.eye(3),
    "concave": np.diag([0.001, 0.01, 0.01]),
    "plateau": np.diag([0.01, 0.001, 0.01]),
    "cylinder": np.diag([1.0, 0.00001, 1.0]),
}


def loop_once(points, faces):
    """One step of Loop subdivision (Warren's weights, libigl's boundary rules) of per-vertex rows."""
    n = len(points)
    edges = {}
    for f in faces:
        for k in range(3):
            a, b, c = f[k], f[(k + 1) % 3], f[(k + 2) % 3]
            edges.setdefault((min(a, b), max(a, b)), []).append(c)
    neighbours = [set() for _ in range(n)]
    boundary = [[] for _ in range(n)]
    for (a, b), opposite in edges.items():
        neighbours[a].add(b), neighbours[b].add(a)
        if len(opposite) == 1:
            boundary[a].append(b), boundary[b].append(a)
    moved = np.empty_like(points)
    for v in range(n):
        if boundary[v]:
            moved[v] = 0.75 * points[v] + 0.125 * points[boundary[v]].sum(axis=0)
        else:
            k = len(neighbours[v])
            beta = 3 / 16 if k == 3 else 3 / (8 * k)
            moved[v] = (1 - k * beta) * points[v] + beta * points[list(neighbours[v])].sum(axis=0)
    index, new_points = {}, []
    for (a, b), opposite in edges.items():
        index[(a, b)] = n + len(new_points)
        if len(opposite) == 1:
            new_points.append(0.5 * (points[a] + points[b]))
        else:
            new_points.append(0.375 * (points[a] + points[b]) + 0.125 * (points[opposite[0]] + points[opposite[1]]))
    mid = lambda a, b: index[(min(a, b), max(a, b))]  # noqa: E731
    new_faces = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        new_faces += [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
    return np.vstack([moved, new_points]), new_faces


def loop_gps(positions, faces, covariances, levels):
    """gps-py's loop_gps: Loop subdivision of the 9D points (Σ⁻¹, Σ⁻¹μ), then back to means."""
    precisions = np.linalg.inv(covariances)
    dual = np.hstack([precisions.reshape(-1, 9), np.einsum("nij,nj->ni", precisions, positions)])
    for _ in range(levels):
        dual, faces = loop_once(dual, faces)
    return np.linalg.solve(dual[:, :9].reshape(-1, 3, 3), dual[:, 9:, None])[..., 0]


cone = gpsurf.sample("cone")
print(f"{'cone':9} {'apex covariance (diagonal)':28} {'apex height':>11}  {'gps-py check':>12}")
for name, apex in APEX.items():
    covariances = cone.covariances.copy()
    covariances[0] = apex
    mesh = cone.copy()
    mesh.covariances = covariances
    subdivided = gpsurf.subdivide(mesh, levels=LEVELS, limit=False, scheme="loop", loop_beta="warren")
    expected = loop_gps(cone.positions, cone.faces.tolist(), covariances, LEVELS)
    difference = np.abs(subdivided.positions[:mesh.n_vertices] - expected[:mesh.n_vertices]).max()
    assert difference < 1e-9, (name, difference)
    # The limit surface's apex: vertex 0 is the corner (u, v) = (0, 0) of patch 0.
    apex_height = gpsurf.Surface(mesh, scheme="loop", loop_beta="warren").evaluate(0, 0.0, 0.0)[0][0, 1]
    diagonal = ", ".join(f"{d:g}" for d in np.diag(apex))
    print(f"{name:9} {diagonal:28} {apex_height:11.5f}  {difference:12.1e}")
print("ok: gps-py's five cones, subdivided as gps-py subdivides them")
