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


def test_importing_without_numpy_says_so():
    # A Python without numpy: the extension's own import failed with "initialization failed".
    script = "import sys; sys.modules['numpy'] = None; import gpsurf"
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert result.returncode == 1, result.stderr
    assert "ImportError: gpsurf needs numpy in this Python (" in result.stderr, result.stderr


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


def test_integer_arrays_too_large_to_copy_raise_memory_error():
    # Once a segfault: the failed copy to int64 was read as an array.
    script = """if True:
        import numpy as np, gpsurf
        mesh = gpsurf.sample('cone')
        surface = gpsurf.Surface(mesh)
        calls = (lambda: surface.evaluate(np.broadcast_to(np.int64(0), (2**40,)), 0.1, 0.1),
                 lambda: gpsurf.Mesh(mesh.positions, np.broadcast_to(np.array([0, 1, 2]), (2**40, 3))),
                 lambda: surface.update(mesh, changed=np.broadcast_to(np.int32(0), (2**40,))))
        for call in calls:
            try:
                call()
            except MemoryError as e:
                print(e)"""
    result = run_script(script)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "out of memory: the arguments ask for more than this machine can hold\n" * 3


def test_a_daemon_thread_in_a_call_when_the_interpreter_exits_lets_it_exit():
    # Once an abort: the thread taking the GIL back at exit was ended by an unwind through a noexcept
    # destructor. One thread is in a background call, the other in calls run in the calling thread.
    script = """if True:
        import threading, time, numpy as np, gpsurf
        mesh = gpsurf.sample('icosphere', 327680)
        surface = gpsurf.Surface(gpsurf.sample('cone'))
        def evaluate():
            while True:
                surface.evaluate(np.zeros(4000, np.int64), 0.1, 0.1)
        threading.Thread(target=lambda: gpsurf.simplify(mesh, 100), daemon=True).start()
        threading.Thread(target=evaluate, daemon=True).start()
        time.sleep(0.3)
        print('exits')"""
    result = run_script(script)
    assert result.returncode == 0 and result.stdout == "exits\n", result.stderr
    # The thread finalizing the interpreter still computes: a finalizer's calls return.
    script = """if True:
        import gc, gpsurf
        gc.disable()  # the cycle below is collected as the interpreter finalizes, not before
        class Computes:
            def __del__(self):
                surface = gpsurf.Surface(gpsurf.sample('cone'))
                print(surface.evaluate(0, 0.1, 0.1)[0].shape)
        kept = Computes()
        kept.cycle = kept
        del kept"""
    result = run_script(script, timeout=60)
    assert result.returncode == 0 and result.stdout == "(1, 3)\n", result.stderr


def test_paths_with_a_null_byte_are_refused_as_open_refuses_them(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    cube = gpsurf.sample("cube")
    cube.write("c.obj")
    calls = [lambda: cube.write("a\0b.obj"), lambda: gpsurf.read("c.obj\0x.obj"),
             lambda: gpsurf.read(b"c.obj\0x.obj")]
    if hasattr(gpsurf, "write_image"):
        calls += [lambda: gpsurf.write_image("a\0b.png", np.zeros((2, 2, 3), np.float32)),
                  lambda: gpsurf.read_image("a\0b.png")]
    for call in calls:
        with pytest.raises(ValueError, match="path: embedded null byte"):
            call()
    if hasattr(gpsurf, "render"):
        with pytest.raises(ValueError, match="matcap: embedded null byte"):
            gpsurf.render(cube, 8, 8, matcap="clay\0.png")
    assert sorted(os.listdir(tmp_path)) == ["c.obj"]


def test_paths_are_encoded_as_os_fsencode_encodes_them(tmp_path, monkeypatch):
    # A file name that is not UTF-8 comes from os.listdir as a str with a lone surrogate.
    monkeypatch.chdir(tmp_path)
    gpsurf.sample("cube").write(b"\xff.obj")
    (name,) = os.listdir(".")
    assert name == "\udcff.obj"
    assert gpsurf.read(name).n_vertices == 8
    gpsurf.sample("cone").write(name)
    assert gpsurf.read(b"\xff.obj").n_vertices == gpsurf.sample("cone").n_vertices


def test_points_beyond_the_positions_limit_are_refused_and_named():
    cone = gpsurf.sample("cone")
    points = gpsurf.tessellate(cone, 4)[0]
    far = np.array([[0.0, 0, 0], [1e155, 0, 0]])
    with pytest.raises(ValueError, match=r"points: row 1 has a coordinate 1e\+155 beyond ±1e\+100"):
        gpsurf.distance(far, cone)
    with pytest.raises(ValueError, match=r"a: row 1 has a coordinate 1e\+155 beyond ±1e\+100"):
        gpsurf.compare(far, cone)
    with pytest.raises(ValueError, match=r"target: row \d+ has a coordinate .* beyond ±1e\+100"):
        gpsurf.fit(cone, points * 1e101, 3)
    with pytest.raises(ValueError, match=r"positions: row 1 has a coordinate 1e\+160 beyond ±1e\+100"):
        gpsurf.Mesh(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.]]) * 1e160, [[0, 1, 2], [0, 2, 3]])
    # Targets within the limit may still draw the fitted control points past it: refused, not handed
    # out as a Mesh that could not be pickled.
    try:
        fitted = gpsurf.fit(cone, points / np.abs(points).max() * 9.9e99, 3)
    except gpsurf.Error as e:
        assert re.search(r"the fitted mesh: vertex \d+ has a coordinate .* beyond ±1e\+100", str(e))
    else:
        assert np.abs(fitted.positions).max() <= 1e100


def test_edit_names_a_number_that_is_not_finite_and_takes_numpy_values():
    cube = gpsurf.sample("cube")
    with pytest.raises(ValueError, match=r'ops\[1\] \(extrude\): "distance" is not finite'):
        gpsurf.edit(cube, [{"op": "extrude", "faces": [0], "distance": 0.1},
                           {"op": "extrude", "faces": [1], "distance": math.nan}])
    with pytest.raises(ValueError, match=r'ops\[0\] \(extrude\): "distance" is not finite'):
        gpsurf.edit(cube, [{"op": "extrude", "faces": [0], "distance": np.float32(np.inf)}])
    expected = gpsurf.edit(cube, [{"op": "extrude", "faces": [0, 2], "distance": 0.25}])
    for faces, distance in (([np.int64(0), np.int32(2)], np.float64(0.25)), (np.array([0, 2]), np.float32(0.25))):
        edited = gpsurf.edit(cube, ({"op": "extrude", "faces": faces, "distance": distance},))
        assert np.array_equal(edited.positions, expected.positions)


def test_text_that_is_not_unicode_is_refused_in_words():
    cube = gpsurf.sample("cube")
    with pytest.raises(ValueError, match="ops holds a lone surrogate, which is not text"):
        gpsurf.edit(cube, '[{"op": "\ud800"}]')
    with pytest.raises(ValueError, match=r'ops\[0\]: "op" holds a lone surrogate'):
        gpsurf.edit(cube, [{"op": "\ud800"}])
    with pytest.raises(ValueError, match=r'ops\[0\] \(transform\): "name" holds a lone surrogate'):
        gpsurf.edit(cube, [{"op": "transform", "name": ["\udcff"]}])


@pytest.mark.skipif(not hasattr(gpsurf, "write_image"), reason="built without GL")
def test_pixels_that_are_not_finite_are_refused_where_the_format_cannot_hold_them(tmp_path):
    image = np.zeros((3, 4, 3), np.float32)
    image[1, 2, 1] = np.nan
    for name in ("a.png", "b.jpg", "c.ppm", "d.bmp", "e.tif"):
        with pytest.raises(ValueError, match=r"image: pixel \(1, 2\) is not finite"):
            gpsurf.write_image(tmp_path / name, image)
    assert os.listdir(tmp_path) == []
    gpsurf.write_image(tmp_path / "f.exr", image)
    assert np.isnan(gpsurf.read_image(tmp_path / "f.exr")[1, 2, 1])


def test_a_second_init_is_refused_instead_of_ignored():
    cube, cone = gpsurf.sample("cube"), gpsurf.sample("cone")
    with pytest.raises(TypeError, match="Mesh: already initialised"):
        cube.__init__(cone.positions, cone.faces)
    assert cube.n_vertices == 8
    surface = gpsurf.Surface(cube)
    with pytest.raises(TypeError, match="Surface: already initialised"):
        surface.__init__(cone)
    assert surface.mesh.n_vertices == 8
    # One made without __init__ takes it, even after a method read its empty state.
    mesh = gpsurf.Mesh.__new__(gpsurf.Mesh)
    assert mesh.n_vertices == 0
    mesh.__init__(cone.positions, cone.faces)
    assert mesh.n_vertices == cone.n_vertices


def test_integers_out_of_range_and_wrong_creases_are_refused_in_words():
    cube = gpsurf.sample("cube")
    surface = gpsurf.Surface(cube)
    refusals = [
        (lambda: gpsurf.tessellate(cube, 2**31), "level: expected 1..64, got 2147483648"),
        (lambda: surface.tessellate(-2**64), "level: expected 1..64, got -18446744073709551616"),
        (lambda: gpsurf.tessellate(cube, 2, depth=2**31), "depth: 2147483648 out of range"),
        (lambda: gpsurf.Surface(cube, depth=-2**40), "depth: -1099511627776 out of range"),
        (lambda: gpsurf.fit(cube, cube, iterations=2**31), "iterations: expected 0..1000, got 2147483648"),
        (lambda: gpsurf.distance(cube, cube, level=2**63), "level: expected 1..64, got 9223372036854775808"),
        (lambda: gpsurf.subdivide(cube, 2**31), "levels: expected 0..8, got 2147483648"),
        (lambda: gpsurf.sample("grid", 2**31), "size: 2147483648 out of range"),
        (lambda: gpsurf.simplify(cube, -1), "vertices: expected at least 4, got -1"),
    ]
    if hasattr(gpsurf, "render"):
        refusals += [(lambda: gpsurf.render(cube, width=2**31), "width: expected 1..[0-9]+, got 2147483648"),
                     (lambda: surface.render(16, 16, level=-1), "level: expected 0..64, got -1")]
    for call, message in refusals:
        with pytest.raises(ValueError, match=message):
            call()
    for creases in ([(0, 1)], [(0.0, 1, 2.0)], [(0, None, 2.0)], None, 5):
        with pytest.raises(TypeError, match=r"creases: expected a sequence of \(a, b, sharpness\) triples"):
            cube.creases = creases
    with pytest.raises(TypeError, match="positions: expected an array of numbers"):
        gpsurf.Mesh([[0, 0, 0], [1, 0], [1, 1, 0]], [[0, 1, 2]])
    # numpy's integers stand for ints.
    assert len(gpsurf.tessellate(cube, np.int64(2))[2]) == len(gpsurf.tessellate(cube, 2)[2])


def test_arguments_of_the_wrong_type_or_name_are_named_as_python_names_them():
    # pybind11 answered each with its list of overloads and the arguments' reprs.
    cube = gpsurf.sample("cube")
    cases = [
        (lambda: gpsurf.subdivide(cube, scheme=None), r"^subdivide\(\): scheme must be str, not NoneType$"),
        (lambda: gpsurf.subdivide(cube, report="yes"), r"^subdivide\(\): got an unexpected keyword argument 'report'$"),
        (lambda: gpsurf.tessellate(cube, "8"), r"^tessellate\(\): level must be int, not str$"),
        (lambda: gpsurf.simplify(cube, vertices=1.5), r"^simplify\(\): vertices must be int or None, not float$"),
        (lambda: gpsurf.subdivide("cube.obj"), r"^subdivide\(\): mesh must be gpsurf.Mesh, not str$"),
        (lambda: gpsurf.subdivide(), r"^subdivide\(\): missing a required argument: 'mesh'$"),
        (lambda: gpsurf.Surface(None), r"^Surface\(\): mesh must be gpsurf.Mesh, not NoneType$"),
        (lambda: cube.copy(3), r"^Mesh.copy\(\): too many positional arguments$"),
    ]
    for call, message in cases:
        with pytest.raises(TypeError, match=message) as raised:
            call()
        assert "incompatible" not in str(raised.value) and "_gpsurf" not in str(raised.value)
    # The right types still go through, numpy's integers among them.
    assert gpsurf.subdivide(cube, levels=np.int64(1), scheme="auto").n_faces == 24


def test_ops_that_hold_themselves_or_nest_too_deep_are_refused_instead_of_crashing():
    # Once a segfault: the ops were walked into JSON by recursion without a bound.
    script = (
        "import gpsurf\n"
        "op = {'op': 'extrude', 'faces': [0], 'distance': 0.5}\n"
        "op['self'] = op\n"
        "faces = [0]\n"
        "faces.append(faces)\n"
        "deep = [0]\n"
        "for _ in range(100000): deep = [deep]\n"
        "for ops in ([op], [{'op': 'extrude', 'faces': faces}], [{'op': 'extrude', 'faces': deep}]):\n"
        "    try:\n"
        "        gpsurf.edit(gpsurf.sample('cube'), ops)\n"
        "    except ValueError as e:\n"
        "        print(e)\n"
    )
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == [
        'ops[0] (extrude): "self" is nested more than 64 levels deep (or holds itself)',
        'ops[0] (extrude): "faces" is nested more than 64 levels deep (or holds itself)',
        'ops[0] (extrude): "faces" is nested more than 64 levels deep (or holds itself)',
    ]
