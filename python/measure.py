"""Measures the module's overhead and its threads (figures of issue 28; not a test: wall-clock).

usage: PYTHONPATH=build/python /usr/bin/python3 python/measure.py DGGVTP MESH_1M [RUNS]
  1. MESH_1M, distances(0, epsilon=1e-4) from Python (wall time of the call, and its thread CPU
     time) against the library's own propagation time for the same query (dggvtp --stats
     seconds_propagate, wall): medians of RUNS. On a loaded machine compare CPU times instead:
     measure_propagation.cpp prints the library's thread CPU time for the same call.
  2. bunny, 8 calls distances(s, epsilon=1e-4): in one thread, then shared by two threads on one
     solver: throughput ratio, median of RUNS."""
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import threading
import time

import dggvtp

cli, big = sys.argv[1], sys.argv[2]
runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
bunny = pathlib.Path(__file__).resolve().parents[1] / "data" / "meshes" / "bunny.ply"

solver = dggvtp.GeodesicSolver(*dggvtp.read_mesh(big))
python_s, python_cpu, library_s = [], [], []
with tempfile.TemporaryDirectory() as tmp:
    stats = pathlib.Path(tmp) / "stats.json"
    for _ in range(runs):  # interleaved, so that both see the same load
        t0, c0 = time.perf_counter(), time.thread_time()
        solver.distances(0, epsilon=1e-4, threads=1)
        python_s.append(time.perf_counter() - t0)
        python_cpu.append(time.thread_time() - c0)  # the call runs in this thread (threads=1)
        subprocess.run([cli, big, "--source", "0", "--epsilon", "1e-4", "--threads", "1", "--stats", stats, "--quiet"],
                       check=True)
        library_s.append(json.loads(stats.read_text())["seconds_propagate"])
p, l = statistics.median(python_s), statistics.median(library_s)
print(f"{pathlib.Path(big).name}, {solver.num_vertices} vertices, epsilon 1e-4, source 0, {runs} runs")
print(f"  Python distances(): median {p:.3f} s {sorted(round(x, 3) for x in python_s)}")
print(f"  Python distances(), thread CPU: median {statistics.median(python_cpu):.3f} s "
      f"{sorted(round(x, 3) for x in python_cpu)}")
print(f"  library propagate:  median {l:.3f} s {sorted(round(x, 3) for x in library_s)}")
print(f"  ratio {p / l:.3f}")

small = dggvtp.GeodesicSolver(*dggvtp.read_mesh(bunny))
sources = [0, 4000, 8000, 12000, 16000, 20000, 24000, 28000]


def run(chunk):
    for s in chunk:
        small.distances(s, epsilon=1e-4, threads=1)  # the Python threads are the parallelism here


ratios = []
for _ in range(runs):
    t0 = time.perf_counter()
    run(sources)
    one = time.perf_counter() - t0
    threads = [threading.Thread(target=run, args=(sources[k::2],)) for k in range(2)]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    two = time.perf_counter() - t0
    ratios.append(one / two)
print(f"bunny, {len(sources)} calls: two threads / one thread throughput: median {statistics.median(ratios):.2f} "
      f"{sorted(round(r, 2) for r in ratios)}")
