"""The module's whole API against the command line and the core's reference: fit, distance and
compare, a Surface's own tessellation and render, the covariance at an evaluated point, the patch to
face map, faces of several sizes, path-like arguments, pickling, copies and reprs."""
import copy
import pathlib
import pickle
import re

import numpy as np
import pytest

import gpsurf


def test_surface_tessellate_uses_its_plans_and_follows_update():
    pawn = gpsurf.sample("pawn")
    surface = gpsurf.Surface(pawn)
    for a, b in zip(surface.tessellate(4), gpsurf.tessellate(pawn, 4)):
        assert np.array_equal(a, b)
    covariances = pawn.covariances.copy()
    covariances[10] *= 0.01
    pawn.covariances = covariances
    surface.update(pawn)
    assert surface.mesh.n_vertices == pawn.n_vertices
    assert np.array_equal(surface.tessellate(4)[0], gpsurf.tessellate(pawn, 4)[0])


def test_evaluate_gives_the_limit_covariance_of_the_reference():
    # At a patch corner of a triangle mesh under Loop the limit point is the base vertex's limit,
    # which the reference gives with its covariance.
    cone = gpsurf.sample("cone-concave")
    surface = gpsurf.Surface(cone, scheme="loop")
    limit = gpsurf.subdivide(cone, levels=0, limit=True, scheme="loop")
    faces = cone.faces
    positions, du, dv, normals, covariances = surface.evaluate(np.arange(8), 0.0, 0.0, covariances=True)
    assert covariances.shape == (8, 3, 3)
    for patch in range(8):
        vertex = faces[patch][0]
        assert np.allclose(positions[patch], limit.positions[vertex], atol=1e-12)
        assert np.allclose(covariances[patch], limit.covariances[vertex], rtol=1e-9, atol=1e-15)


def test_patch_faces_maps_each_patch_to_its_face():
    cylinder = gpsurf.sample("cylinder")  # 16 quads and two octagons
    surface = gpsurf.Surface(cylinder)
    assert surface.scheme == "catmull-clark"
    faces = surface.patch_faces
    assert len(faces) == surface.n_patches == 16 + 2 * 8
    counts = np.bincount(faces, minlength=cylinder.n_faces)
    sizes = np.diff(cylinder.face_offsets)
    assert np.array_equal(counts, np.where(sizes == 4, 1, sizes))
    # Each patch's centre lies nearer its own face's centroid than any other face's.
    centres = surface.evaluate(np.arange(surface.n_patches), 0.5, 0.5)[0]
    indices, offsets = cylinder.face_indices, cylinder.face_offsets
    centroids = np.array([cylinder.positions[indices[offsets[f]:offsets[f + 1]]].mean(axis=0)
                          for f in range(cylinder.n_faces)])
    quads = sizes[faces] == 4
    nearest = np.argmin(np.linalg.norm(centres[:, None] - centroids[None], axis=2), axis=1)
    assert np.array_equal(nearest[quads], faces[quads])
    loop = gpsurf.Surface(gpsurf.sample("cone"))
    assert np.array_equal(loop.patch_faces, np.arange(8))


def test_faces_of_several_sizes_are_offsets_and_indices():
    cylinder = gpsurf.sample("cylinder")
    with pytest.raises(ValueError, match="face_offsets and face_indices"):
        cylinder.faces
    offsets, indices = cylinder.face_offsets, cylinder.face_indices
    faces = [indices[offsets[f]:offsets[f + 1]] for f in range(cylinder.n_faces)]
    made = gpsurf.Mesh(cylinder.positions, faces, cylinder.covariances)
    assert np.array_equal(made.face_indices, indices) and np.array_equal(made.face_offsets, offsets)
    quads = gpsurf.sample("cube")
    assert np.array_equal(gpsurf.Mesh(quads.positions, quads.faces).faces, quads.faces)


def test_distance_and_compare_equal_the_command_line(tmp_path, cli):
    cli("sample", "pawn", "-o", "pawn.ply")
    cli("simplify", "pawn.ply", "-o", "coarse.ply", "--vertices", 200)
    out = cli("compare", "pawn.ply", "coarse.ply", "--level", 6)
    pawn, coarse = gpsurf.read(tmp_path / "pawn.ply"), gpsurf.read(tmp_path / "coarse.ply")
    summary = gpsurf.compare(pawn, coarse, level=6)
    numbers = [float(x) for x in re.findall(r"([0-9.e+-]+) \(", out)]
    assert len(numbers) == 3, out
    for printed, key in zip(numbers, ("rms", "percentile_99", "max")):
        assert summary[key] == pytest.approx(printed, rel=1e-3), (key, out)
    assert summary["count"] == pawn.n_vertices
    distances = gpsurf.distance(pawn.positions, coarse, level=6)
    assert distances.shape == (pawn.n_vertices,) and distances.max() == pytest.approx(summary["max"])
    assert np.array_equal(gpsurf.distance(pawn, gpsurf.Surface(coarse), level=6), distances)
    # A mesh's own vertices lie on its faces.
    assert gpsurf.distance(coarse, coarse, linear=True).max() < 1e-12


def test_fit_equals_the_command_line(tmp_path, cli):
    cli("sample", "icosphere", "-o", "sphere.ply", "--size", 1280)
    cli("sample", "icosphere", "-o", "coarse.ply", "--size", 80)
    cli("fit", "coarse.ply", "--target", "sphere.ply", "-o", "fitted.ply", "--iterations", 3, "--level", 0)
    expected = gpsurf.read(tmp_path / "fitted.ply")
    fitted = gpsurf.fit(gpsurf.read(tmp_path / "coarse.ply"), gpsurf.read(tmp_path / "sphere.ply"), iterations=3)
    assert np.array_equal(fitted.positions, expected.positions)
    assert np.array_equal(fitted.covariances, expected.covariances)
    before = gpsurf.compare(gpsurf.read(tmp_path / "sphere.ply"), gpsurf.read(tmp_path / "coarse.ply"))
    after = gpsurf.compare(gpsurf.read(tmp_path / "sphere.ply"), fitted)
    assert after["rms"] < before["rms"]


def test_fit_stops_at_the_tolerance_or_the_time_as_the_command_line_does(tmp_path, cli):
    cli("sample", "icosphere", "-o", "sphere.ply", "--size", 1280)
    cli("sample", "icosphere", "-o", "coarse.ply", "--size", 80)
    out = cli("fit", "coarse.ply", "--target", "sphere.ply", "-o", "fitted.ply", "--iterations", 50, "--level", 0,
              "--tolerance", 0.2)
    expected = gpsurf.read(tmp_path / "fitted.ply")
    coarse, sphere = gpsurf.read(tmp_path / "coarse.ply"), gpsurf.read(tmp_path / "sphere.ply")
    fitted, report = gpsurf.fit(coarse, sphere, iterations=50, tolerance=0.2, report=True)
    assert report["stop"] == "converged" and report["iterations"] < 50
    assert f"stopped after {report['iterations']} iterations: {report['reason']}" in out
    assert np.array_equal(fitted.positions, expected.positions)
    assert np.array_equal(fitted.covariances, expected.covariances)
    rms = report["relative_rms"]
    assert len(rms) == report["iterations"] + 1 and rms[-2] - rms[-1] <= 0.2 * rms[-2]
    # Tolerance 0 runs every iteration; the default return is the Mesh alone.
    assert gpsurf.fit(coarse, sphere, iterations=report["iterations"] + 1, report=True)[1]["stop"] == "iterations"
    assert isinstance(gpsurf.fit(coarse, sphere, iterations=1, tolerance=0.2), gpsurf.Mesh)
    timed, timed_report = gpsurf.fit(coarse, sphere, iterations=50, time=1e-6, report=True)
    assert timed_report["stop"] == "time" and timed_report["iterations"] == 1
    for bad in ({"tolerance": -0.1}, {"tolerance": 1.5}, {"tolerance": float("nan")}, {"time": 0.0},
                {"time": float("inf")}, {"time": float("nan")}):
        with pytest.raises(ValueError, match=next(iter(bad))):
            gpsurf.fit(coarse, sphere, iterations=1, **bad)


def test_paths_may_be_path_like(tmp_path):
    mesh = gpsurf.sample("cone")
    path = pathlib.Path(tmp_path) / "cone.ply"
    mesh.write(path)
    assert np.array_equal(gpsurf.read(path).positions, mesh.positions)
    assert np.array_equal(gpsurf.read(bytes(path)).positions, mesh.positions)
    with pytest.raises(TypeError):
        gpsurf.read(3)


def test_meshes_pickle_and_copy_exactly():
    cube = gpsurf.sample("cube")
    cube.creases = [(0, 1, 2.5)]
    cube.corners = [0.0] * 7 + [1.5]
    for back in (pickle.loads(pickle.dumps(cube)), copy.deepcopy(cube), copy.copy(cube), cube.copy()):
        assert isinstance(back, gpsurf.Mesh)
        assert np.array_equal(back.positions, cube.positions)
        assert np.array_equal(back.covariances, cube.covariances)
        assert np.array_equal(back.faces, cube.faces)
        assert back.creases == cube.creases and np.array_equal(back.corners, cube.corners)
    cylinder = gpsurf.sample("cylinder")
    assert np.array_equal(pickle.loads(pickle.dumps(cylinder)).face_indices, cylinder.face_indices)


def test_reprs_say_what_an_object_is():
    cube = gpsurf.sample("cube")
    assert repr(cube) == "<gpsurf.Mesh: 8 vertices, 6 faces>"
    assert repr(gpsurf.Surface(cube)) == "<gpsurf.Surface: catmull-clark, 6 patches of a mesh of 8 vertices>"
    assert gpsurf.Mesh.__module__ == "gpsurf" and gpsurf.Surface.__module__ == "gpsurf"


@pytest.mark.skipif(not hasattr(gpsurf, "render"), reason="built without GL")
def test_surface_render_equals_render():
    cone = gpsurf.sample("cone-pointy")
    image = gpsurf.render(cone, 64, 48, camera=(30, 20))
    assert np.array_equal(gpsurf.Surface(cone).render(64, 48, camera=(30, 20)), image)


def square_grid(n):
    """An n x n grid of quads over [-1, 1]² in the plane z = 0."""
    xs = np.linspace(-1, 1, n + 1)
    x, y = np.meshgrid(xs, xs)
    positions = np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], axis=1)
    faces = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i]
             for j in range(n) for i in range(n)]
    return gpsurf.Mesh(positions, np.array(faces))


@pytest.mark.skipif(not hasattr(gpsurf, "render"), reason="built without GL")
def test_render_colours_by_scalars_through_the_colormap():
    grid = square_grid(12)
    right = (grid.positions[:, 0] > 0).astype(float)
    ends = {"viridis": ((0x44, 0x01, 0x54), (0xfd, 0xe7, 0x25)), "coolwarm": ((0x3b, 0x4c, 0xc0), (0xb4, 0x04, 0x26)),
            "gray": ((0, 0, 0), (255, 255, 255))}
    for colormap, (low, high) in ends.items():
        image = gpsurf.render(grid, 200, 200, scalars=right, colormap=colormap)
        # The scalar is 0 on the left half and 1 on the right; away from the middle its limit is too.
        assert np.allclose(image[100, 30:60, :3], np.array(low) / 255, atol=1 / 255), colormap
        assert np.allclose(image[100, 140:170, :3], np.array(high) / 255, atol=1 / 255), colormap
        assert np.array_equal(gpsurf.Surface(grid).render(200, 200, scalars=right, colormap=colormap), image)
    # A range past the scalars' own maps them inside it: 0 and 1 of [-1, 3] at a quarter and a half.
    image = gpsurf.render(grid, 200, 200, scalars=right, colormap="gray", scalar_range=(-1, 3))
    assert np.allclose(image[100, 30, :3], 0x40 / 255, atol=1 / 255)
    assert np.allclose(image[100, 170, :3], 0x80 / 255, atol=1 / 255)
    # Without scalars, the surface's own shading.
    assert not np.allclose(gpsurf.render(grid, 200, 200)[100, 30, :3], np.array(ends["viridis"][0]) / 255, atol=0.05)
    for bad in ({"scalars": right[:-1]}, {"scalars": np.where(right > 0, np.nan, 0)}, {"colormap": "jet"},
                {"scalars": right, "scalar_range": (1, 1)}, {"scalars": right, "scalar_range": (0, np.inf)},
                {"scalar_range": (0, 1)}):
        with pytest.raises(ValueError, match=list(bad)[-1]):
            gpsurf.render(grid, 32, 32, **bad)
