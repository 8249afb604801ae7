"""The Python module's costs (issue 38; docs/python.md): stepping from Python against
`clothlab trace` on the default 32 x 32 scene, and a 64-case sweep on a LocalCluster of two
single-threaded workers against the same cases run serially, with the per-task overhead. Run it
alone on an idle machine: `scripts/bench python` (prints the tables, writes out/bench/python.csv).
"""
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import clothlab

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLI = os.path.join(ROOT, "build/release/apps/clothlab")
SCENE = os.path.join(ROOT, "scenes/default.toml")
STEPS = 4000  # per call; the target is stated for calls of at least 1000 steps
ROUNDS = 5

# The sweep's cases: a 32 x 32 sheet for 2 s, 8 stiffnesses x 8 damping values, each at
# symplectic Euler's automatic step (about 0.05-0.2 s of work a case on one core).
SWEEP_SCENE = """
[cloth]
size = [1.0, 1.0]
resolution = [32, 32]
origin = [-0.5, 1.5, 0.0]
u_axis = [1, 0, 0]
v_axis = [0, -1, 0]
mass = 0.3
pins = [[0, 0], [31, 0]]

[solver]
integrator = "symplectic_euler"
dt = "auto"
precision = "double"
"""
DURATION = 2.0
GRID = {
    "springs.stiffness": [200.0 * (k + 1) for k in range(8)],
    "springs.damping": [0.01 * (k + 1) for k in range(8)],
}


def trace_ms_per_step(dt):
    """`clothlab trace`'s own ms/step (file output excluded) for STEPS steps."""
    out = os.path.join(ROOT, "out/bench/python_bench_trace.csv")
    r = subprocess.run(
        [CLI, "trace", SCENE, "--duration", repr(STEPS * dt), "--out", out,
         "--set", "trace.every=1000000"],
        capture_output=True, text=True, check=True,
    )
    return float(re.search(r"([0-9.e+-]+) ms/step", r.stdout).group(1))


def python_ms_per_step(scene):
    sim = clothlab.Simulation(scene)
    sim.step(100)
    start = time.perf_counter()
    sim.step(STEPS)
    return 1e3 * (time.perf_counter() - start) / STEPS, sim.dt


def stepping(rows):
    scene = clothlab.Scene.from_file(SCENE)
    python, trace = [], []
    for _ in range(ROUNDS):  # alternating, so drifts in the machine's load hit both
        ms, dt = python_ms_per_step(scene)
        python.append(ms)
        trace.append(trace_ms_per_step(dt))
    p, t = statistics.median(python), statistics.median(trace)
    print(f"stepping, default scene (32 x 32, {STEPS} steps a call, median of {ROUNDS}):")
    print(f"  clothlab trace {t:.4f} ms/step, Simulation.step {p:.4f} ms/step: "
          f"{100.0 * (p / t - 1.0):+.1f} %")
    rows.append(["stepping", "trace_ms_per_step", t])
    rows.append(["stepping", "python_ms_per_step", p])


def sweep(rows):
    from dask.distributed import Client, LocalCluster

    scene = clothlab.Scene.from_toml(SWEEP_SCENE)
    start = time.perf_counter()
    serial = clothlab.sweep(scene, GRID, DURATION, client="serial")
    serial_s = time.perf_counter() - start
    start = time.perf_counter()
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None, local_directory=tempfile.gettempdir()) as cluster, \
            Client(cluster) as client:
        client.wait_for_workers(2)
        startup_s = time.perf_counter() - start
        start = time.perf_counter()
        parallel = clothlab.sweep(scene, GRID, DURATION, client=client)
        parallel_s = time.perf_counter() - start
        start = time.perf_counter()
        clothlab.sweep(scene, GRID, 0.0, client=client)  # no steps: the tasks' own cost
        empty_cluster_s = time.perf_counter() - start
    start = time.perf_counter()
    clothlab.sweep(scene, GRID, 0.0, client="serial")
    empty_serial_s = time.perf_counter() - start
    same = serial.drop(columns="wall_seconds").equals(parallel.drop(columns="wall_seconds"))
    n = len(serial)
    overhead_ms = 1e3 * (2.0 * empty_cluster_s - empty_serial_s) / n
    print(f"sweep, {n} cases (32 x 32 sheet, {DURATION} s each), 2 cores:")
    print(f"  serial {serial_s:.2f} s; LocalCluster of 2 workers {parallel_s:.2f} s "
          f"({serial_s / parallel_s:.2f}x), its start {startup_s:.2f} s; rows equal: {same}")
    print(f"  per-task overhead on the cluster: {overhead_ms:.1f} ms of a worker's time "
          f"(64 cases without steps: {1e3 * empty_serial_s / n:.1f} ms a case serially, "
          f"{1e3 * empty_cluster_s:.0f} ms for all on 2 workers)")
    rows += [
        ["sweep", "serial_s", serial_s],
        ["sweep", "local_cluster_s", parallel_s],
        ["sweep", "speedup", serial_s / parallel_s],
        ["sweep", "cluster_start_s", startup_s],
        ["sweep", "task_overhead_ms", overhead_ms],
    ]


def main():
    os.makedirs(os.path.join(ROOT, "out/bench"), exist_ok=True)
    rows = []
    stepping(rows)
    sweep(rows)
    path = os.path.join(ROOT, "out/bench/python.csv")
    with open(path + ".tmp", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["part", "measure", "value"])
        writer.writerows(rows)
    os.replace(path + ".tmp", path)
    print(f"wrote {path}")


if __name__ == "__main__":
    sys.exit(main())
