"""The Python module against the command line (bit for bit where both compute the same thing) and
against the math's properties."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import gpsurf

SOURCE_DIR = os.environ.get("GPSURF_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def read_obj(path):
    """Positions, normals and triangles (from 0) of an OBJ as gpsurf writes it."""
    points, normals, triangles = [], [], []
    with open(path) as f:
        for line in f:
            words = line.split()
            if words and words[0] == "v":
                points.append([float(w) for w in words[1:4]])
            elif words and words[0] == "vn":
                normals.append([float(w) for w in words[1:4]])
            elif words and words[0] == "f":
                triangles.append([int(w.split("/")[0]) - 1 for w in words[1:4]])
    return np.array(points), np.array(normals), np.array(triangles)


def test_version_and_samples():
    assert gpsurf.__version__.count(".") == 2
    assert "cone-pointy" in gpsurf.samples()
    mesh = gpsurf.sample("cone-pointy")
    assert (mesh.n_vertices, mesh.n_faces) == (9, 8)
    assert mesh.positions.shape == (9, 3) and mesh.covariances.shape == (9, 3, 3)
    assert np.array_equal(mesh.covariances[0], 1e-5 * np.eye(3))
    assert mesh.faces.shape == (8, 3) and mesh.faces.dtype == np.int32 and mesh.faces[0][0] == 0


def test_write_then_read_is_exact(tmp_path):
    mesh = gpsurf.sample("pawn")
    rng = np.random.default_rng(7)
    mesh.positions = mesh.positions + rng.normal(scale=1e-3, size=mesh.positions.shape)
    for binary in (False, True):
        path = tmp_path / f"pawn{int(binary)}.ply"
        mesh.write(path, binary=binary)
        back = gpsurf.read(path)
        assert np.array_equal(back.positions, mesh.positions)
        assert np.array_equal(back.covariances, mesh.covariances)
        assert np.array_equal(back.face_offsets, mesh.face_offsets)
        assert np.array_equal(back.face_indices, mesh.face_indices)


def test_mesh_from_arrays_infers_as_the_reader_does(tmp_path, cli):
    cli("sample", "wirecube", "-o", "w.obj")
    plain = gpsurf.read(str(tmp_path / "w.obj"))
    made = gpsurf.Mesh(plain.positions, plain.faces)
    assert np.array_equal(made.covariances, plain.covariances)
    cli("infer", "w.obj", "-o", "inferred.ply", "--bias", "0.2")
    assert np.array_equal(gpsurf.infer(plain, bias=0.2).covariances, gpsurf.read(str(tmp_path / "inferred.ply")).covariances)


def test_subdivide_equals_the_command_line(tmp_path, cli):
    cli("sample", "cone-concave", "-o", "cone.ply")
    cone = gpsurf.read(str(tmp_path / "cone.ply"))
    for scheme in ("loop", "catmull-clark"):
        cli("subdivide", "cone.ply", "-o", f"{scheme}.ply", "--levels", 3, "--scheme", scheme, "--limit")
        expected = gpsurf.read(str(tmp_path / f"{scheme}.ply"))
        got = gpsurf.subdivide(cone, 3, limit=True, scheme=scheme)
        assert np.array_equal(got.positions, expected.positions), scheme
        assert np.array_equal(got.covariances, expected.covariances), scheme
        assert np.array_equal(got.faces, expected.faces)
    # auto: Loop on a mesh of triangles
    assert np.array_equal(gpsurf.subdivide(cone, 3).positions, gpsurf.read(str(tmp_path / "loop.ply")).positions)


def test_tessellate_equals_the_command_line(tmp_path, cli):
    cli("sample", "pawn", "-o", "pawn.ply")
    cli("tessellate", "pawn.ply", "-o", "pawn.obj", "--level", 5)
    points, normals, triangles = gpsurf.tessellate(gpsurf.read(str(tmp_path / "pawn.ply")), 5)
    expected = read_obj(tmp_path / "pawn.obj")
    assert np.array_equal(points, expected[0])
    assert np.array_equal(normals, expected[1])
    assert np.array_equal(triangles, expected[2])


def test_evaluation_meets_the_tessellation_and_its_derivatives():
    mesh = gpsurf.sample("wirecube")
    surface = gpsurf.Surface(mesh)
    assert surface.scheme == "catmull-clark" and surface.patch_corners == 4
    patches = np.arange(surface.n_patches)
    corners, du, dv, normals = surface.evaluate(patches, 0.0, 0.0)
    assert corners.shape == (surface.n_patches, 3)
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0)
    # du against a central difference of positions
    h = 1e-6
    plus = surface.evaluate(patches, 0.5 + h, 0.5)[0]
    minus = surface.evaluate(patches, 0.5 - h, 0.5)[0]
    mid_du = surface.evaluate(patches, 0.5, 0.5)[1]
    assert np.allclose((plus - minus) / (2 * h), mid_du, atol=1e-6)
    with pytest.raises(IndexError):
        surface.evaluate(surface.n_patches, 0.5, 0.5)
    with pytest.raises(ValueError):
        surface.evaluate(0, 1.5, 0.5)


def test_scaling_every_covariance_leaves_the_surface():
    mesh = gpsurf.sample("pawn")
    scaled = mesh.copy()
    scaled.covariances = 7.0 * mesh.covariances
    a = gpsurf.tessellate(mesh, 3)[0]
    b = gpsurf.tessellate(scaled, 3)[0]
    assert np.allclose(a, b, atol=1e-12)


def test_update_after_editing_a_gaussian_equals_planning_again():
    mesh = gpsurf.sample("cone")
    surface = gpsurf.Surface(mesh)
    covariances = mesh.covariances.copy()
    covariances[0] = np.diag([1e-3, 1e-5, 1e-3])
    mesh.covariances = covariances
    surface.update(mesh, [0])
    patches = np.arange(surface.n_patches)
    assert np.array_equal(surface.evaluate(patches, 0.25, 0.25)[0], gpsurf.Surface(mesh).evaluate(patches, 0.25, 0.25)[0])


def test_edit_equals_the_command_line(tmp_path, cli):
    ops = [{"op": "loop_cut", "edge": [0, 1], "cuts": 2}, {"op": "extrude", "faces": [1], "distance": 0.5}]
    (tmp_path / "ops.json").write_text(json.dumps(ops))
    cli("edit", "sample:cube", "-o", "edited.ply", "--ops", "@ops.json")
    expected = gpsurf.read(str(tmp_path / "edited.ply"))
    got = gpsurf.edit(gpsurf.sample("cube"), ops)
    assert (got.n_vertices, got.n_faces) == (8 + 8 + 4, 6 + 8 + 4)
    assert np.array_equal(got.positions, expected.positions)
    assert np.array_equal(got.covariances, expected.covariances)
    assert np.array_equal(got.face_indices, expected.face_indices)
    assert np.array_equal(gpsurf.edit(gpsurf.sample("cube"), json.dumps(ops)).face_indices, got.face_indices)
    with pytest.raises(gpsurf.Error, match=r"ops\[0\] \(merge\): vertex 99 is not in the mesh"):
        gpsurf.edit(gpsurf.sample("cube"), [{"op": "merge", "vertices": [0, 99]}])


def test_errors_carry_the_one_line_message(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nf 1 2 9\n")
    with pytest.raises(gpsurf.Error, match="bad.obj"):
        gpsurf.read(str(bad))
    with pytest.raises(gpsurf.Error, match="scheme must be"):
        gpsurf.subdivide(gpsurf.sample("cone"), 1, scheme="butterfly")
    with pytest.raises(ValueError, match="positions"):
        gpsurf.Mesh(np.zeros((3, 2)), [[0, 1, 2]])
    mesh = gpsurf.sample("cone")
    with pytest.raises(gpsurf.Error, match="vertex 2"):
        covariances = mesh.covariances.copy()
        covariances[2] = -np.eye(3)
        mesh.covariances = covariances
    assert np.array_equal(mesh.covariances, gpsurf.sample("cone").covariances)  # unchanged by the refused edit


@pytest.mark.skipif(not hasattr(gpsurf, "render"), reason="built without GL")
def test_render_equals_the_command_line(tmp_path, cli):
    cli("sample", "cone-pointy", "-o", "cone.ply")
    cli("render", "cone.ply", "-o", "cone.exr", "--size", "160x120", "--camera", "30,20")
    expected = gpsurf.read_image(str(tmp_path / "cone.exr"))
    got = gpsurf.render(gpsurf.read(str(tmp_path / "cone.ply")), 160, 120, camera=(30, 20))
    assert got.shape == (120, 160, 4) and got.dtype == np.float32
    assert np.array_equal(got, expected)
    assert (got[..., :3] < 0.9).any()  # the surface is in the picture, not only the white background


@pytest.mark.parametrize("example", ["cones.py", "inference.py"])
def test_examples_run(tmp_path, example):
    script = os.path.join(SOURCE_DIR, "examples", "python", example)
    result = subprocess.run([sys.executable, script], cwd=tmp_path, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "ok" in result.stdout.splitlines()[-1]


def test_creases_and_corners_round_trip_and_change_the_surface(tmp_path):
    cube = gpsurf.sample("cube")
    smooth = gpsurf.subdivide(cube, levels=2)
    cube.creases = [(4, 5, 10.0), (5, 6, 10.0), (6, 7, 10.0), (4, 7, 10.0)]
    cube.corners = [0.0] * 7 + [2.5]
    assert cube.creases == ((4, 5, 10.0), (4, 7, 10.0), (5, 6, 10.0), (6, 7, 10.0))
    assert np.array_equal(cube.crease_edges, [[4, 5], [4, 7], [5, 6], [6, 7]])
    assert np.array_equal(cube.crease_sharpness, [10.0] * 4)
    assert cube.corners[7] == 2.5
    path = str(tmp_path / "creased.ply")
    cube.write(path)
    back = gpsurf.read(path)
    assert back.creases == cube.creases and np.array_equal(back.corners, cube.corners)
    creased = gpsurf.subdivide(cube, levels=2)
    assert np.abs(creased.positions - smooth.positions).max() > 1e-2
    with pytest.raises(Exception, match="not an edge"):
        cube.creases = [(0, 6, 1.0)]
    with pytest.raises(ValueError, match="negative"):
        cube.creases = [(0, 1, -1.0)]


def test_simplify_keeps_a_closed_mesh_closed():
    sphere = gpsurf.sample("icosphere", 1280)
    coarse = gpsurf.simplify(sphere, vertices=100)
    assert coarse.n_vertices == 100
    assert coarse.n_faces == 2 * 100 - 4  # Euler: a closed genus-0 triangle mesh
