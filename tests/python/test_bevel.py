"""gpsurf.edit's bevel: the op list's operation, as gpsurf edit runs it."""
import json
import math

import numpy as np
import pytest

import gpsurf


def signed_volume(mesh):
    """The volume the faces enclose, positive where they are oriented outward."""
    p, offsets, indices = mesh.positions, mesh.face_offsets, mesh.face_indices
    six_volume = 0.0
    for f in range(mesh.n_faces):
        corners = indices[offsets[f] : offsets[f + 1]]
        for k in range(1, len(corners) - 1):
            six_volume += np.dot(p[corners[0]], np.cross(p[corners[k]], p[corners[k + 1]]))
    return six_volume / 6


def test_bevel_of_a_cube_edge_and_vertex_runs_from_python(tmp_path, cli):
    cube = gpsurf.sample("cube")
    ops = [{"op": "bevel", "edges": [[4, 5]], "width": 0.25, "segments": 2}]
    got = gpsurf.edit(cube, ops)
    assert (got.n_vertices, got.n_faces) == (12, 8)
    assert signed_volume(got) == pytest.approx(8 - 2 * 0.0625 * (1 - 1 / math.sqrt(2)), abs=1e-12)
    (tmp_path / "ops.json").write_text(json.dumps(ops))
    cli("edit", "sample:cube", "-o", "bevelled.ply", "--ops", "@ops.json")
    expected = gpsurf.read(str(tmp_path / "bevelled.ply"))
    assert np.array_equal(got.positions, expected.positions)
    assert np.array_equal(got.covariances, expected.covariances)
    assert np.array_equal(got.face_indices, expected.face_indices)

    corner = gpsurf.edit(cube, [{"op": "bevel", "vertices": [4], "width": 0.5}])
    assert (corner.n_vertices, corner.n_faces) == (10, 7)
    assert signed_volume(corner) == pytest.approx(8 - 0.5**3 / 6, abs=1e-12)
    assert (cube.n_vertices, cube.n_faces) == (8, 6)


def test_bevel_refusals_name_the_edge_and_the_key():
    cube = gpsurf.sample("cube")
    with pytest.raises(gpsurf.Error, match=r"ops\[0\] \(bevel\): edge 0–6 is not in the mesh"):
        gpsurf.edit(cube, [{"op": "bevel", "edges": [[0, 6]], "width": 0.1}])
    with pytest.raises(gpsurf.Error, match=r"ops\[0\] \(bevel\): \"segments\" must be an integer from 1 to 100"):
        gpsurf.edit(cube, [{"op": "bevel", "edges": [[4, 5]], "width": 0.1, "segments": 0}])
