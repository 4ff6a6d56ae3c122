"""Benchmarks of the Python module's threading (python/README.md): two threads tessellating a
surface each against one thread doing one, and how long Ctrl-C takes to stop a long call.

    PYTHONPATH=build/python python3 bench/bench_python.py [--repeat N]
"""
import argparse
import os
import signal
import statistics
import subprocess
import sys
import textwrap
import threading
import time

import gpsurf


def tessellation_seconds(surface, threads, level):
    """Wall time of `threads` threads each tessellating `surface` once, all started together."""
    start = threading.Barrier(threads + 1)

    def work():
        start.wait()
        surface.tessellate(level)

    workers = [threading.Thread(target=work) for _ in range(threads)]
    for w in workers:
        w.start()
    start.wait()
    t0 = time.perf_counter()
    for w in workers:
        w.join()
    return time.perf_counter() - t0


CHILD = textwrap.dedent("""
    import sys, time
    import gpsurf
    sphere = gpsurf.sample("icosphere", 327680)
    surface = gpsurf.Surface(gpsurf.sample("icosphere", 20480))

    def tessellate():
        for _ in range(1000):
            surface.tessellate(16)

    calls = {"simplify": lambda: gpsurf.simplify(sphere, 100), "tessellate": tessellate}
    print("ready", flush=True)
    try:
        calls[sys.argv[1]]()
    except KeyboardInterrupt:
        print(time.monotonic(), flush=True)
""")


def interrupt_latency(call):
    """Seconds from SIGINT sent to KeyboardInterrupt caught, a second into `call`."""
    child = subprocess.Popen([sys.executable, "-c", CHILD, call], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "ready"
    time.sleep(1.0)
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
    surface = gpsurf.Surface(gpsurf.sample("icosphere", 20480))
    surface.tessellate(args.level)  # warm
    one = statistics.median(tessellation_seconds(surface, 1, args.level) for _ in range(args.repeat))
    two = statistics.median(tessellation_seconds(surface, 2, args.level) for _ in range(args.repeat))
    print(f"tessellate icosphere 20480 at level {args.level} ({os.cpu_count()} cores, median of {args.repeat}): "
          f"1 thread {one:.3f} s, 2 threads {two:.3f} s, ratio {two / one:.2f}")
    for call in ("simplify", "tessellate"):
        latencies = [interrupt_latency(call) for _ in range(args.repeat)]
        print(f"Ctrl-C during {call}: median {statistics.median(latencies) * 1000:.0f} ms, "
              f"max {max(latencies) * 1000:.0f} ms")


if __name__ == "__main__":
    main()
