"""Preiner's cone (the GPS paper's demo): one apex Gaussian over a ring of eight, and the limit
surface's apex height for each apex covariance, under Loop with limit projection.

The plain cone's apex sinks far below its control point (y = 1.5); a small apex covariance pulls the
surface up to it (a sharp tip), an anisotropic one makes a concave tip, a plateau or a cylinder.
"""
import numpy as np

import gpsurf

# Apex heights of an independent Loop GPS implementation (Loop's beta, limit projection).
EXPECTED = {
    "cone": 0.11744,
    "cone-pointy": 1.49744,
    "cone-concave": 1.26376,
    "cone-plateau": 1.49744,
    "cone-cylinder": 1.49744,
}

print(f"{'sample':15} {'apex covariance (diagonal)':30} {'apex height':>12} {'expected':>9}")
for name, expected in EXPECTED.items():
    mesh = gpsurf.sample(name)
    surface = gpsurf.Surface(mesh, scheme="loop")
    # The apex is vertex 0, the corner (u, v) = (0, 0) of patch 0.
    position = surface.evaluate(0, 0.0, 0.0)[0][0]
    # The same point by the exact reference: subdivision in 9D, then the limit of the apex vertex.
    reference = gpsurf.subdivide(mesh, levels=2, limit=True, scheme="loop").positions[0]
    assert abs(position[1] - reference[1]) < 1e-12, (name, position, reference)
    assert abs(position[1] - expected) < 5e-6, (name, position[1], expected)
    diagonal = ", ".join(f"{d:g}" for d in np.diag(mesh.covariances[0]))
    print(f"{name:15} {diagonal:30} {position[1]:12.5f} {expected:9.5f}")
print("ok: every apex height as the GPS paper's demo gives it")
