"""The keywords that mirror the command line's options: fit's covariance_smoothness, covariance_prior,
min_sigma, max_sigma, relaxed_min_sigma and normal_weight (--covariance-smoothness ...), simplify's error and quads
(--error, --quads), and compare's angles between normals; each gives what the command line gives and
refuses what it refuses."""
import inspect
import math
import re

import numpy as np
import pytest

import gpsurf


@pytest.fixture
def spheres(tmp_path, cli):
    """A coarse icosphere and a dense one to fit it to, written as coarse.ply and sphere.ply."""
    cli("sample", "icosphere", "-o", "sphere.ply", "--size", 1280)
    cli("sample", "icosphere", "-o", "coarse.ply", "--size", 80)
    return gpsurf.read(tmp_path / "coarse.ply"), gpsurf.read(tmp_path / "sphere.ply")


def fitted_by_command_line(tmp_path, cli, *options):
    """Three iterations: the first two move the means alone (their rms falls by more than 30 %)."""
    cli("fit", "coarse.ply", "--target", "sphere.ply", "-o", "fitted.ply", "--iterations", 3, "--level", 0, *options)
    return gpsurf.read(tmp_path / "fitted.ply")


def same_mesh(a, b):
    return np.array_equal(a.positions, b.positions) and np.array_equal(a.covariances, b.covariances)


def mean_edge_lengths(mesh):
    """Per vertex, the mean length of its edges (each edge once), as the fit scales its bounds by."""
    offsets, indices, p = mesh.face_offsets, mesh.face_indices, mesh.positions
    edges = set()
    for f in range(mesh.n_faces):
        face = indices[offsets[f]:offsets[f + 1]]
        for a, b in zip(face, np.roll(face, -1)):
            edges.add((min(a, b), max(a, b)))
    total, count = np.zeros(mesh.n_vertices), np.zeros(mesh.n_vertices)
    for a, b in edges:
        length = np.linalg.norm(p[a] - p[b])
        total[[a, b]] += length
        count[[a, b]] += 1
    return total / count


def sigmas(mesh):
    """Each covariance's standard deviations, least first."""
    return np.sqrt(np.linalg.eigvalsh(mesh.covariances))


def test_fit_defaults_are_the_command_lines():
    parameters = inspect.signature(gpsurf.fit).parameters
    assert {name: parameters[name].default for name in
            ("covariance_smoothness", "covariance_prior", "min_sigma", "max_sigma", "normal_weight",
             "relaxed_min_sigma")} == {
        "covariance_smoothness": None, "covariance_prior": 0.0, "min_sigma": 0.35, "max_sigma": 1.0,
        "normal_weight": 0.001, "relaxed_min_sigma": 0.1}
    with pytest.raises(TypeError):  # keywords only: no float taken for another by its place
        gpsurf.fit(gpsurf.sample("icosphere", 80), gpsurf.sample("icosphere", 80).positions, 1, False, 1e-5, 0.0,
                   None, None, False, 1e-4)


def test_fit_keeps_each_sigma_within_the_bounds_as_the_command_line_does(tmp_path, cli, spheres):
    coarse, sphere = spheres
    default = gpsurf.fit(coarse, sphere, iterations=3)
    assert same_mesh(default, fitted_by_command_line(tmp_path, cli))
    bounded = gpsurf.fit(coarse, sphere, iterations=3, min_sigma=0.5, max_sigma=0.55)
    assert same_mesh(bounded, fitted_by_command_line(tmp_path, cli, "--min-sigma", 0.5, "--max-sigma", 0.55))
    assert not same_mesh(bounded, default)
    edge = mean_edge_lengths(coarse)[:, None]
    s = sigmas(bounded)
    assert np.all(s >= 0.5 * edge * (1 - 1e-9)) and np.all(s <= 0.55 * edge * (1 + 1e-9))
    # The default bounds leave a wider spread than the tight ones allow.
    spread = sigmas(default) / edge
    assert spread.min() < 0.5 * (1 - 1e-6) or spread.max() > 0.55 * (1 + 1e-6)


def test_fit_relaxes_its_lower_bound_once_converged_unless_asked_not_to(spheres):
    coarse, sphere = spheres
    flat = sphere.positions * np.array([1.0, 1.0, 0.2])  # an ellipsoid whose rims want narrower Gaussians
    relaxed, details = gpsurf.fit(coarse, flat, tolerance=0.02, report=True)
    once, once_details = gpsurf.fit(coarse, flat, tolerance=0.02, relaxed_min_sigma=0.35, report=True)
    assert details["stop"] == "converged" and details["iterations"] > once_details["iterations"]
    assert details["relative_rms"][-1] < once_details["relative_rms"][-1]
    edge = mean_edge_lengths(coarse)[:, None]
    assert np.all(sigmas(once) >= 0.35 * edge * (1 - 1e-9))
    assert np.all(sigmas(relaxed) >= 0.1 * edge * (1 - 1e-9))
    assert np.any(sigmas(relaxed) < 0.35 * edge * (1 - 1e-9))


def test_fit_covariance_weights_act_as_the_command_lines(tmp_path, cli, spheres):
    coarse, sphere = spheres
    default = gpsurf.fit(coarse, sphere, iterations=3)
    smooth = gpsurf.fit(coarse, sphere, iterations=3, covariance_smoothness=10.0)
    assert same_mesh(smooth, fitted_by_command_line(tmp_path, cli, "--covariance-smoothness", 10))
    assert not same_mesh(smooth, default)
    held = gpsurf.fit(coarse, sphere, iterations=3, covariance_prior=1e4)
    assert same_mesh(held, fitted_by_command_line(tmp_path, cli, "--covariance-prior", 10000))
    # The prior keeps the covariances nearer their start than the fit without it.
    change = lambda fitted: np.abs(fitted.covariances - coarse.covariances).sum()  # noqa: E731
    assert change(held) < change(default)
    turned = gpsurf.fit(coarse, sphere, iterations=3, normal_weight=0.5)
    assert same_mesh(turned, fitted_by_command_line(tmp_path, cli, "--normal-weight", 0.5))
    assert not same_mesh(turned, default)
    # An array of points has no normals: the weight changes nothing.
    assert same_mesh(gpsurf.fit(coarse, sphere.positions, iterations=3, normal_weight=0.5),
                     gpsurf.fit(coarse, sphere.positions, iterations=3, normal_weight=0.0))


@pytest.mark.parametrize("bad, words", [
    ({"min_sigma": math.nan}, "min_sigma: expected a number from 0"),
    ({"min_sigma": -0.1}, "min_sigma: expected a number from 0"),
    ({"relaxed_min_sigma": math.nan}, "relaxed_min_sigma: expected a number from 0"),
    ({"relaxed_min_sigma": -1}, "relaxed_min_sigma: expected a number from 0"),
    ({"min_sigma": 1.0}, r"min_sigma: expected below max_sigma \(1.0\)"),
    ({"min_sigma": 0.6, "max_sigma": 0.5}, r"min_sigma: expected below max_sigma \(0.5\)"),
    ({"max_sigma": 0.0}, "max_sigma: expected a finite number above 0"),
    ({"max_sigma": math.inf}, "max_sigma: expected a finite number above 0"),
    ({"max_sigma": math.nan}, "max_sigma: expected a finite number above 0"),
    ({"covariance_smoothness": -1.0}, "covariance_smoothness: expected a number from 0"),
    ({"normal_weight": -1.0}, "normal_weight: expected a number from 0"),
    ({"normal_weight": math.nan}, "normal_weight: expected a number from 0"),
    ({"covariance_smoothness": math.inf}, "covariance_smoothness: expected a number from 0"),
    ({"covariance_prior": math.nan}, "covariance_prior: expected a number from 0"),
    ({"covariance_prior": 2e6}, "covariance_prior: expected a number from 0"),
])
def test_fit_refuses_what_the_command_line_refuses(bad, words):
    cone = gpsurf.sample("cone")
    with pytest.raises(ValueError, match=words):
        gpsurf.fit(cone, cone.positions, iterations=1, **bad)


def test_simplify_error_and_quads_equal_the_command_line(tmp_path, cli):
    cli("sample", "pawn", "-o", "pawn.ply")
    pawn = gpsurf.read(tmp_path / "pawn.ply")
    cli("simplify", "pawn.ply", "-o", "loose.ply", "--error", 0.01, "--level", 0)
    loose = gpsurf.simplify(pawn, error=0.01)
    assert same_mesh(loose, gpsurf.read(tmp_path / "loose.ply"))
    tight = gpsurf.simplify(pawn, error=0.001)
    assert pawn.n_vertices > tight.n_vertices > loose.n_vertices
    # With vertices too, the error stops it short of them; the vertices alone do not.
    assert gpsurf.simplify(pawn, 100, error=0.001).n_vertices == tight.n_vertices
    assert gpsurf.simplify(pawn, 100).n_vertices == 100

    cli("simplify", "pawn.ply", "-o", "quads.ply", "--vertices", 300, "--quads", "--level", 0)
    quads = gpsurf.simplify(pawn, 300, quads=True)
    expected = gpsurf.read(tmp_path / "quads.ply")
    assert same_mesh(quads, expected) and np.array_equal(quads.face_indices, expected.face_indices)
    sizes = np.diff(quads.face_offsets)
    triangles = gpsurf.simplify(pawn, 300)
    assert set(sizes) == {3, 4} and np.all(np.diff(triangles.face_offsets) == 3)
    # Each quad is two of the triangles: the same vertices, one face fewer per quad.
    assert np.array_equal(quads.positions, triangles.positions)
    assert quads.n_faces == triangles.n_faces - np.count_nonzero(sizes == 4)

    cli("simplify", "pawn.ply", "-o", "placed.ply", "--vertices", 300, "--limit", "--level", 0)
    placed = gpsurf.simplify(pawn, 300, limit=True)
    assert same_mesh(placed, gpsurf.read(tmp_path / "placed.ply"))
    assert not np.array_equal(placed.positions, triangles.positions)


@pytest.mark.parametrize("bad, words", [
    ({}, "simplify: give vertices=N or error=E"),
    ({"error": 0.0}, "error: expected a number above 0 and at most 1"),
    ({"error": 1.5}, "error: expected a number above 0 and at most 1"),
    ({"error": math.nan}, "error: expected a number above 0 and at most 1"),
])
def test_simplify_refuses_what_the_command_line_refuses(bad, words):
    with pytest.raises(ValueError, match=words):
        gpsurf.simplify(gpsurf.sample("icosphere", 320), **bad)


def test_compare_gives_the_command_lines_angle_between_normals(tmp_path, cli):
    cli("sample", "pawn", "-o", "pawn.ply")
    cli("simplify", "pawn.ply", "-o", "coarse.ply", "--vertices", 200, "--level", 0)
    out = cli("compare", "pawn.ply", "coarse.ply", "--level", 6)
    printed = re.search(
        r"normals: rms angle ([0-9.e+-]+)° \(max ([0-9.e+-]+)°\) over (\d+) points \((\d+) without a normal left out",
        out,
    )
    assert printed, out
    pawn, coarse = gpsurf.read(tmp_path / "pawn.ply"), gpsurf.read(tmp_path / "coarse.ply")
    summary = gpsurf.compare(pawn, coarse, level=6)
    assert summary["normal_rms_degrees"] == pytest.approx(float(printed[1]), rel=5e-3)
    assert summary["normal_max_degrees"] == pytest.approx(float(printed[2]), rel=5e-3)
    # The pawn's vertices on its sharp rims have no one normal: left out alike.
    assert summary["normal_count"] == int(printed[3]) == pawn.n_vertices - int(printed[4])
    assert 0 < int(printed[4]) < pawn.n_vertices / 4
    # A mesh against its own faces: every normal as the faces' own.
    assert gpsurf.compare(coarse, coarse, linear=True)["normal_rms_degrees"] < 1e-6
    # An array's points have no normals.
    points = gpsurf.compare(pawn.positions, coarse, level=6)
    assert points["normal_count"] == 0 and math.isnan(points["normal_rms_degrees"])
    assert points["rms"] == summary["rms"]
