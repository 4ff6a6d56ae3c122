"""Arguments checked against what they act on: every entry point raises gpsurf.Error, ValueError,
TypeError or IndexError for wrong shapes, types, NaN, empty, huge, negative and out-of-range values,
never crashes the interpreter, and never quietly does nothing or returns NaN."""
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import gpsurf

REFUSALS = (gpsurf.Error, ValueError, TypeError, IndexError)


def test_update_with_a_mesh_of_another_topology_raises_instead_of_crashing():
    # Once a segfault: update checked the changed indices against the new mesh, not the surface's.
    script = "import gpsurf; gpsurf.Surface(gpsurf.sample('cone')).update(gpsurf.sample('pawn'), None)"
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert result.returncode == 1, result.stderr
    assert re.search(r"ValueError: update: the mesh has \d+ vertices, the surface's mesh 9;", result.stderr)


def test_update_replans_a_mesh_of_another_topology_when_asked():
    surface = gpsurf.Surface(gpsurf.sample("cone"))
    pawn = gpsurf.sample("pawn")
    surface.update(pawn, replan=True)
    assert surface.n_patches == gpsurf.Surface(pawn).n_patches
    assert np.array_equal(surface.tessellate(2)[0], gpsurf.tessellate(pawn, 2)[0])


def test_update_refuses_a_changed_list_that_misses_an_edited_vertex():
    mesh = gpsurf.sample("cone")
    surface = gpsurf.Surface(mesh)
    edited = mesh.positions.copy()
    edited[0] += 0.1
    edited[3] += 0.1
    mesh.positions = edited
    with pytest.raises(ValueError, match="vertex 3's Gaussian changed but is not in `changed`"):
        surface.update(mesh, [0])
    surface.update(mesh, [0, 3])
    patches = np.arange(surface.n_patches)
    assert np.array_equal(surface.evaluate(patches, 0.2, 0.2)[0], gpsurf.Surface(mesh).evaluate(patches, 0.2, 0.2)[0])


def test_update_refuses_other_creases():
    cube = gpsurf.sample("cube")
    surface = gpsurf.Surface(cube)
    cube.creases = [(0, 1, 2.0)]
    with pytest.raises(ValueError, match="other creases or corners"):
        surface.update(cube)


def test_arrays_handed_out_refuse_writes():
    mesh = gpsurf.sample("cube")
    mesh.creases = [(0, 1, 2.0)]
    for name in ("positions", "covariances", "faces", "face_offsets", "face_indices", "crease_edges",
                 "crease_sharpness", "corners"):
        array = getattr(mesh, name)
        assert not array.flags.writeable, name
        if array.size:
            with pytest.raises(ValueError, match="read-only"):
                array.flat[0] = 1
    with pytest.raises(AttributeError):
        mesh.creases.append((1, 2, 1.0))
    with pytest.raises(ValueError, match="read-only"):
        mesh.faces[0][0] = 5
    surface = gpsurf.Surface(mesh)
    for array in (*surface.evaluate(0, 0.5, 0.5, covariances=True), *surface.tessellate(2), surface.patch_faces):
        assert not array.flags.writeable


def test_assignments_reach_the_mesh_and_leave_copies():
    mesh = gpsurf.sample("cube")
    copy = mesh.copy()
    positions = mesh.positions.copy()
    positions[0] = (5, 6, 7)
    mesh.positions = positions
    assert np.array_equal(mesh.positions[0], (5, 6, 7))
    assert np.array_equal(copy.positions[0], gpsurf.sample("cube").positions[0])


def test_values_the_command_line_refuses_are_refused():
    cone = gpsurf.sample("cone")
    for bias in (-1.0, 0.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="bias"):
            gpsurf.simplify(gpsurf.sample("icosphere", 320), 40, bias=bias)
        with pytest.raises(ValueError, match="bias"):
            gpsurf.infer(cone, bias=bias)
    surface = gpsurf.Surface(cone)
    with pytest.raises(IndexError, match="patches: 4294967296 out of range 0..7"):
        surface.evaluate(2**32, 0.5, 0.25)
    with pytest.raises(TypeError, match="patches"):
        surface.evaluate(0.7, 0.5, 0.25)
    with pytest.raises(TypeError, match="patches"):
        surface.evaluate([True], 0.5, 0.25)
    with pytest.raises(ValueError, match="domain"):
        surface.evaluate(0, math.nan, 0.25)
    if hasattr(gpsurf, "render"):
        with pytest.raises(ValueError, match="camera"):
            gpsurf.render(cone, 32, 32, camera=[math.nan, 0])


def test_not_finite_values_in_a_mesh_are_named():
    cone = gpsurf.sample("cone")
    positions = cone.positions.copy()
    positions[4, 1] = math.nan
    with pytest.raises(ValueError, match="positions: row 4 is not finite"):
        gpsurf.Mesh(positions, cone.faces)
    with pytest.raises(ValueError, match="positions: row 4 is not finite"):
        cone.positions = positions
    covariances = cone.covariances.copy()
    covariances[5, 0, 0] = math.inf
    with pytest.raises(gpsurf.Error, match="vertex 5 has a covariance that is not finite"):
        gpsurf.Mesh(cone.positions, cone.faces, covariances)


# Every entry point with valid arguments (and keywords, where it has keyword-only ones); the fuzz
# replaces one argument or keyword at a time.
def entry_points():
    cone = gpsurf.sample("cone")
    surface = gpsurf.Surface(cone)
    points = cone.positions
    calls = {
        "Mesh": (gpsurf.Mesh, [cone.positions, cone.faces, cone.covariances]),
        "read": (gpsurf.read, ["missing.obj", "infer", 0.05, 0.5]),
        "sample": (gpsurf.sample, ["grid", 16]),
        "infer": (gpsurf.infer, [cone, 0.05]),
        "subdivide": (gpsurf.subdivide, [cone, 1, True, "auto", "loop"]),
        "tessellate": (gpsurf.tessellate, [cone, 2, "auto", "loop", -1, False]),
        "simplify": (gpsurf.simplify, [gpsurf.sample("icosphere", 80), 20, 0.05], {"error": 0.01, "quads": True}),
        "edit": (gpsurf.edit, [cone, [{"op": "extrude", "faces": [0], "distance": 0.1}]]),
        "fit": (gpsurf.fit, [cone, points, 1], {"covariance_smoothness": 1e-4, "covariance_prior": 0.1,
                                                "min_sigma": 0.3, "max_sigma": 2.0}),
        "distance": (gpsurf.distance, [points, cone, 2]),
        "compare": (gpsurf.compare, [points, surface, 2]),
        "Surface": (gpsurf.Surface, [cone, "auto", "loop", -1, False]),
        "Surface.evaluate": (surface.evaluate, [[0, 1], [0.2, 0.3], 0.1]),
        "Surface.update": (surface.update, [cone, [0]]),
        "Surface.tessellate": (surface.tessellate, [2]),
    }
    if hasattr(gpsurf, "render"):
        calls["render"] = (gpsurf.render, [cone, 16, 16, 2])
        calls["Surface.render"] = (surface.render, [16, 16, 2])
    return calls


BAD_VALUES = [None, "", "x", b"\xff", -1, 0, 2**31, 2**63, -2**63, 2**64, 0.7, math.nan, math.inf, -math.inf, True,
              [], [[]], [1, 2], np.zeros((0, 3)), np.zeros((5, 2)), np.full((9, 3), np.nan), np.zeros((9, 3, 3)),
              np.zeros((3, 3), dtype=np.int8), np.array([2**63], dtype=np.uint64), np.array(["a"]), object(),
              [{"op": "nonsense"}], [{"op": "merge", "vertices": [0, 2**40]}]]


def fuzz():
    """Calls every entry point with each bad value in place of each argument: anything but a
    refusal or a valid result fails, and so does NaN in a result."""
    for name, (function, arguments, *keywords) in entry_points().items():
        given = keywords[0] if keywords else {}
        for position in [*range(len(arguments)), *given]:
            for bad in BAD_VALUES:
                args, kwargs = list(arguments), dict(given)
                if isinstance(position, int):
                    args[position] = bad
                else:
                    kwargs[position] = bad
                try:
                    result = function(*args, **kwargs)
                except REFUSALS:
                    continue
                except Exception as e:  # noqa: BLE001
                    raise AssertionError(f"{name} argument {position} = {bad!r}: {type(e).__name__}: {e}") from e
                for array in result if isinstance(result, tuple) else [result]:
                    if isinstance(array, gpsurf.Mesh):
                        array = array.covariances
                    if isinstance(array, np.ndarray) and array.dtype.kind == "f" and name != "Surface.evaluate":
                        assert np.isfinite(array).all(), f"{name} argument {position} = {bad!r}: not finite"
    print("fuzz: ok")


def test_fuzz_never_loses_the_interpreter(tmp_path):
    here = os.path.dirname(os.path.abspath(__file__))
    script = f"import sys; sys.path.insert(0, {here!r}); import test_safety; test_safety.fuzz()"
    result = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr[-4000:]
    assert "fuzz: ok" in result.stdout


def run_script(script, timeout=120):
    """`script` in a fresh interpreter: its exit status and output, a crash as a negative status."""
    return subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=timeout)


def test_two_threads_making_the_first_arrays_at_once_do_not_wait_on_each_other():
    # numpy was imported by neither: the module set its C API up when it was imported.
    script = """if True:
        import threading, gpsurf
        m = gpsurf.sample('cube')
        threads = [threading.Thread(target=lambda: [m.positions for _ in range(50)]) for _ in range(4)]
        for t in threads: t.start()
        for t in threads: t.join()
        print('ok')"""
    result = run_script(script, timeout=60)
    assert result.returncode == 0 and result.stdout == "ok\n", result.stderr


@pytest.mark.skipif(not hasattr(gpsurf, "render"), reason="built without GL")
def test_renders_from_several_threads_take_their_turns():
    script = """if True:
        import threading, gpsurf
        m = gpsurf.sample('cube')
        images, errors = [], []
        def draw():
            try:
                images.append(gpsurf.render(m, width=48, height=32))
            except Exception as e:
                errors.append(repr(e))
        threads = [threading.Thread(target=draw) for _ in range(6)]
        for t in threads: t.start()
        for t in threads: t.join()
        print(len(images), errors, all((i == images[0]).all() for i in images))"""
    result = run_script(script)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "6 [] True\n", result.stdout + result.stderr


def test_every_pickle_protocol_gives_the_mesh_and_the_surface_back():
    import pickle

    mesh = gpsurf.sample("cube")
    mesh.creases = [(0, 1, 2.0)]
    surface = gpsurf.Surface(mesh, depth=3)
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        copy = pickle.loads(pickle.dumps(mesh, protocol))
        assert np.array_equal(copy.positions, mesh.positions) and copy.creases == mesh.creases
        again = pickle.loads(pickle.dumps(surface, protocol))
        assert again.n_patches == surface.n_patches
        assert np.array_equal(again.tessellate(2)[0], surface.tessellate(2)[0])


def test_instances_made_without_init_hold_an_empty_mesh():
    script = """if True:
        import gpsurf
        m = gpsurf.Mesh.__new__(gpsurf.Mesh)
        s = gpsurf.Surface.__new__(gpsurf.Surface)
        print(repr(m), m.positions.shape, repr(s), s.tessellate(2)[0].shape)"""
    result = run_script(script)
    assert result.returncode == 0, result.stderr
    assert result.stdout == (
        "<gpsurf.Mesh: 0 vertices, 0 faces> (0, 3) "
        "<gpsurf.Surface: catmull-clark, 0 patches of a mesh of 0 vertices> (0, 3)\n")


def test_a_pickled_state_of_other_types_and_a_size_past_memory_are_refused_in_words():
    with pytest.raises(TypeError, match="an item is not of its type"):
        gpsurf.Mesh.__new__(gpsurf.Mesh).__setstate__((1, 2, 3, 4, 5, 6))
    # An existing mesh given a state that is not one is refused too, and left as it was.
    mesh = gpsurf.sample("cube")
    with pytest.raises(TypeError, match="a tuple of 6 items, not NoneType"):
        mesh.__setstate__(None)
    for state in ((1, 2, 3), ()):
        with pytest.raises(ValueError, match="a pickled state of 6 items expected"):
            mesh.__setstate__(state)
    assert mesh.n_vertices == 8
    copy = gpsurf.Mesh.__new__(gpsurf.Mesh)
    copy.__setstate__(mesh.__getstate__())
    assert copy.n_vertices == 8 and copy.n_faces == 6
    with pytest.raises(MemoryError, match="out of memory"):
        gpsurf.Mesh(np.zeros((3, 3)), range(10**12))


@pytest.mark.skipif(not hasattr(gpsurf, "write_image"), reason="built without GL")
def test_images_without_pixels_or_past_jpegs_size_are_refused(tmp_path):
    for name, shape in (("a.ppm", (0, 0, 3)), ("b.bmp", (4, 0, 3)), ("c.png", (0, 4, 3))):
        with pytest.raises(gpsurf.Error, match="at least one pixel"):
            gpsurf.write_image(tmp_path / name, np.zeros(shape, np.float32))
    with pytest.raises(gpsurf.Error, match="at most 65500 pixels a side"):
        gpsurf.write_image(tmp_path / "tall.jpg", np.zeros((70000, 1, 3), np.float32))


def test_indices_past_int64_or_int_are_named_as_given_and_an_empty_list_is_no_index():
    mesh = gpsurf.sample("cube")
    surface = gpsurf.Surface(mesh)
    with pytest.raises(IndexError, match="patches: 18446744073709551615 out of range"):
        surface.evaluate(np.array([2**64 - 1], np.uint64), 0.5, 0.5)
    with pytest.raises(IndexError, match="face 0 refers to vertex 4294967298"):
        gpsurf.Mesh(mesh.positions, np.array([[0, 1, 2**32 + 2]], np.int64))
    surface.update(mesh, changed=[])  # nothing changed, nothing named
