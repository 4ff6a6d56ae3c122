"""gpsurf.edit's knife: the op list's operation, as gpsurf edit runs it."""
import pytest

import gpsurf


def test_knife_across_the_cube_top_from_python():
    cube = gpsurf.sample("cube")
    got = gpsurf.edit(cube, [{"op": "knife", "points": [[0, -1, 1], [0, 1, 1]]}])
    assert (got.n_vertices, got.n_faces) == (10, 7)
    assert got.positions[8].tolist() == pytest.approx([0, -1, 1], abs=1e-14)
    assert (cube.n_vertices, cube.n_faces) == (8, 6)
    with pytest.raises(gpsurf.Error, match=r"ops\[0\] \(knife\): point 2 is not on the mesh"):
        gpsurf.edit(cube, [{"op": "knife", "points": [[0, -1, 1], [0, 1, 3]]}])
