"""Calls that compute let other Python threads run, stop on Ctrl-C, and report progress to a callback
that can cancel them. (The timings, two threads against one and Ctrl-C's latency, are measured by
bench/bench_python.py.)"""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import gpsurf


def ticks_during(call):
    """How often the calling thread got to run while `call` ran on another thread."""
    done = threading.Event()
    errors = []

    def run():
        try:
            call()
        except Exception as e:  # noqa: BLE001
            errors.append(e)
        done.set()

    thread = threading.Thread(target=run)
    ticks = 0
    thread.start()
    while not done.wait(0.001):
        ticks += 1
    thread.join()
    assert not errors, errors
    return ticks


@pytest.fixture(scope="module")
def sphere():
    return gpsurf.sample("icosphere", 20480)


def test_other_threads_run_while_a_call_computes(sphere, tmp_path):
    # Each call takes a few hundred milliseconds; a call that held the GIL would leave the calling
    # thread about one tick.
    surface = gpsurf.Surface(sphere)
    rng = np.random.default_rng(1)
    n = 400_000
    patches = rng.integers(0, surface.n_patches, n)
    u = rng.uniform(0, 0.5, n)
    path = tmp_path / "sphere.ply"
    sphere.write(path)
    finer = gpsurf.sample("icosphere", 81920)  # planning or simplifying the sphere alone can take under 20 ms
    calls = {
        "Surface": lambda: gpsurf.Surface(finer),
        "evaluate": lambda: surface.evaluate(patches, u, u),
        "tessellate": lambda: surface.tessellate(12),
        "subdivide": lambda: gpsurf.subdivide(sphere, 2),
        "simplify": lambda: gpsurf.simplify(finer, 2000),
        "read": lambda: [gpsurf.read(path) for _ in range(5)],
    }
    for name, call in calls.items():
        assert ticks_during(call) >= 20, name


def test_progress_is_reported_and_a_false_answer_cancels(sphere):
    fractions = []
    coarse = gpsurf.simplify(sphere, 500, progress=fractions.append)
    assert coarse.n_vertices == 500
    assert fractions[-1] == 1.0 and fractions == sorted(fractions)
    # Long enough to be asked (progress is polled every 20 ms; the small sphere may finish before).
    finer = gpsurf.sample("icosphere", 81920)
    with pytest.raises(gpsurf.Cancelled):
        gpsurf.simplify(finer, 500, progress=lambda fraction: False)

    def failing(fraction):
        raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        gpsurf.simplify(sphere, 500, progress=failing)
    # An answer whose truth raises raises too (it once read as False, cancelling without a word).
    with pytest.raises(ValueError, match="truth value"):
        gpsurf.simplify(sphere, 500, progress=lambda fraction: np.array([True, False]))
    fitted = []
    gpsurf.fit(gpsurf.sample("icosphere", 80), sphere, iterations=2, progress=fitted.append)
    assert fitted[-1] == 1.0


INTERRUPTED = textwrap.dedent("""
    import sys, time
    import gpsurf

    def started(fraction=None):
        if not started.said:
            print("started", flush=True)
            started.said = True

    started.said = False

    def simplify():  # interrupted once it reports progress, long before it ends
        gpsurf.simplify(gpsurf.sample("icosphere", 327680), 100, progress=started)

    def tessellate():  # about a minute
        surface = gpsurf.Surface(gpsurf.sample("icosphere", 20480))
        started()
        for _ in range(200):
            surface.tessellate(16)

    try:
        {"simplify": simplify, "tessellate": tessellate}[sys.argv[1]]()
        print("finished")
    except KeyboardInterrupt:
        print("interrupted", time.monotonic())
""")


@pytest.mark.parametrize("call", ["simplify", "tessellate"])
def test_ctrl_c_stops_a_long_call(call):
    child = subprocess.Popen([sys.executable, "-c", INTERRUPTED, call], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "started"
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=120)
    assert child.returncode == 0
    assert out.startswith("interrupted"), out


def test_a_call_keeps_the_surface_it_was_given_while_another_thread_updates_it(sphere):
    surface = gpsurf.Surface(sphere)
    scaled = sphere.copy()
    scaled.positions = 2 * sphere.positions
    before, after = gpsurf.tessellate(sphere, 6)[0], gpsurf.tessellate(scaled, 6)[0]
    results = []
    readers = [threading.Thread(target=lambda: results.append(surface.tessellate(6)[0])) for _ in range(4)]
    for r in readers:
        r.start()
    for mesh in (scaled, sphere, scaled):
        surface.update(mesh)  # between, during or after the readers' calls: each sees one whole state
    for r in readers:
        r.join()
    assert len(results) == 4
    assert all(np.array_equal(r, before) or np.array_equal(r, after) for r in results)
    assert np.array_equal(surface.tessellate(6)[0], after)


def thread_ids():
    return set(os.listdir("/proc/self/task"))


def test_calls_one_after_another_reuse_one_worker_thread():
    # A thread per call would start OpenMP's team and core's per-thread caches again on every call.
    sphere = gpsurf.sample("sphere", 20000)
    extrude = [{"op": "extrude", "faces": [0], "distance": 0.5}]
    gpsurf.edit(sphere, extrude)
    known = thread_ids()
    seen, stop = set(), threading.Event()

    def watch():  # every thread that exists while the calls run, however briefly
        seen.add(str(threading.get_native_id()))
        while not stop.is_set():
            seen.update(thread_ids())

    watcher = threading.Thread(target=watch)
    watcher.start()
    for _ in range(20):
        gpsurf.edit(sphere, extrude)
    stop.set()
    watcher.join()
    assert seen - {str(watcher.native_id)} <= known


def test_calls_from_several_threads_each_get_their_result_and_a_forked_child_still_computes():
    sphere = gpsurf.sample("sphere", 2000)
    started = threading.Barrier(3)
    results = []

    def call():
        started.wait()
        results.append(gpsurf.edit(sphere, [{"op": "subdivide"}]).n_faces)

    callers = [threading.Thread(target=call) for _ in range(3)]
    for t in callers:
        t.start()
    for t in callers:
        t.join()
    assert results == [4 * sphere.n_faces] * 3
    # The child has none of the parent's worker threads: its calls make their own.
    pid = os.fork()
    if pid == 0:
        os._exit(0 if gpsurf.edit(sphere, [{"op": "subdivide"}]).n_faces == 4 * sphere.n_faces else 1)
    _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
