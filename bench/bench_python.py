"""Benchmarks of the Python module's threading (python/README.md): two threads tessellating a
surface each against one thread doing one (Surface.tessellate from kept plans, and
gpsurf.tessellate(mesh), which plans too), and how long Ctrl-C takes to stop a long call.

    PYTHONPATH=build/python python3 bench/bench_python.py [--repeat N]
"""
import argparse
import hashlib
import os
import signal
import statistics
import subprocess
import sys
import textwrap
import threading
import time

import gpsurf


def seconds_on_threads(call, threads):
    """Wall time of `threads` threads each making `call` once, all started together, and the share of
    that time the calls overlapped (1: all ran at once, 0: one after another, as under the GIL)."""
    start = threading.Barrier(threads + 1)
    spans = []

    def work():
        start.wait()
        begin = time.perf_counter()
        call()
        spans.append((begin, time.perf_counter()))

    workers = [threading.Thread(target=work) for _ in range(threads)]
    for w in workers:
        w.start()
    start.wait()
    t0 = time.perf_counter()
    for w in workers:
        w.join()
    wall = time.perf_counter() - t0
    overlap = max(0.0, min(end for _, end in spans) - max(begin for begin, _ in spans)) / wall
    return wall, overlap


def ticks_during(call):
    """How often a thread sleeping 1 ms at a time woke while `call` ran on the calling thread."""
    done = threading.Event()
    ticks = [0]

    def tick():
        while not done.is_set():
            time.sleep(0.001)
            ticks[0] += 1

    ticker = threading.Thread(target=tick)
    ticker.start()
    t0 = time.perf_counter()
    call()
    seconds = time.perf_counter() - t0
    done.set()
    ticker.join()
    return ticks[0], seconds


def cores_free():
    """Two threads of hashlib (which releases the GIL) against one: what the machine allows now."""
    data = b"x" * (100 * 1024 * 1024)
    one = seconds_on_threads(lambda: hashlib.sha256(data).digest(), 1)[0]
    return seconds_on_threads(lambda: hashlib.sha256(data).digest(), 2)[0] / one


CHILD = textwrap.dedent("""
    import sys, time
    import gpsurf
    sphere = gpsurf.sample("icosphere", 327680)
    mesh = gpsurf.sample("icosphere", 20480)

    def tessellate():
        for _ in range(1000):
            gpsurf.tessellate(mesh, 16)

    calls = {"simplify": lambda: gpsurf.simplify(sphere, 100), "tessellate": tessellate}
    print("ready", flush=True)
    try:
        calls[sys.argv[1]]()
    except KeyboardInterrupt:
        print(time.monotonic(), flush=True)
""")


def interrupt_latency(call):
    """Seconds from SIGINT sent to KeyboardInterrupt caught, half a second into `call`."""
    child = subprocess.Popen([sys.executable, "-c", CHILD, call], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "ready"
    time.sleep(0.5)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    caught = float(child.stdout.readline())
    child.wait()
    return caught - sent


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--level", type=int, default=16)
    args = parser.parse_args()
    mesh = gpsurf.sample("icosphere", 20480)
    calls = {"gpsurf.tessellate(mesh)": lambda: gpsurf.tessellate(mesh, args.level)}
    if hasattr(gpsurf.Surface, "tessellate"):
        surface = gpsurf.Surface(mesh)
        calls["Surface.tessellate"] = lambda: surface.tessellate(args.level)
    print(f"the machine now: two threads of hashlib take {cores_free():.2f}x one ({os.cpu_count()} cores, load "
          f"{os.getloadavg()[0]:.1f})")
    for name, call in calls.items():
        call()  # warm
        one = statistics.median(seconds_on_threads(call, 1)[0] for _ in range(args.repeat))
        runs = [seconds_on_threads(call, 2) for _ in range(args.repeat)]
        two = statistics.median(wall for wall, _ in runs)
        overlap = statistics.median(o for _, o in runs)
        ticks, seconds = ticks_during(call)
        print(f"{name}, icosphere 20480 at level {args.level} (median of {args.repeat}): 1 thread {one:.3f} s, "
              f"2 threads {two:.3f} s, ratio {two / one:.2f}, calls overlapping {overlap:.0%} of the time; a 1 ms "
              f"ticker woke {ticks} times during one call of {seconds:.3f} s")
    for call in ("simplify", "tessellate"):
        latencies = [interrupt_latency(call) for _ in range(args.repeat)]
        print(f"Ctrl-C during {call}: median {statistics.median(latencies) * 1000:.0f} ms, "
              f"max {max(latencies) * 1000:.0f} ms")


if __name__ == "__main__":
    main()
