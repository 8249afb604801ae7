"""Shared pieces of the Python module's tests: the repository, the command line, a small
scene that runs in a fraction of a second and a Dask scheduler with two worker processes."""
import contextlib
import json
import os
import pathlib
import subprocess
import sys
import time

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

# A 12 x 12 sheet hanging from two corners in a steady breeze, double precision.
SMALL_SCENE = """
[cloth]
size = [1.0, 1.0]
resolution = [12, 12]
origin = [-0.5, 1.5, 0.0]
u_axis = [1, 0, 0]
v_axis = [0, -1, 0]
mass = 0.3
pins = [[0, 0], [11, 0]]

[forces]
wind = { velocity = [2, 0, 1], gust = 0.3, seed = 3 }

[solver]
integrator = "symplectic_euler"
dt = 0.0005
threads = 1
precision = "double"

[trace]
vertices = [[6, 11], [0, 11]]
every = 10
"""


@pytest.fixture
def root():
    return ROOT


@pytest.fixture
def small_scene_text():
    return SMALL_SCENE


def clothlab_binary():
    return os.environ.get("CLOTHLAB_BINARY", str(ROOT / "build/release/apps/clothlab"))


def cli_trace(folder, scene_text, duration):
    """Writes the scene to folder/sheet.toml and traces it with the command line; returns the
    scene file and the CSV read with exact doubles (pandas' round_trip parser)."""
    import pandas

    scene_file = folder / "sheet.toml"
    scene_file.write_text(scene_text)
    out = folder / "trace.csv"
    code, _, err = run_cli("trace", str(scene_file), "--duration", repr(duration), "--out", str(out))
    assert code == 0, err
    return scene_file, pandas.read_csv(out, float_precision="round_trip")


def run_cli(*args):
    """Runs the command line; returns (exit status, stdout, stderr)."""
    r = subprocess.run([clothlab_binary(), *args], capture_output=True, text=True, timeout=300)
    return r.returncode, r.stdout, r.stderr


def wait_for(path, seconds):
    deadline = time.monotonic() + seconds
    while not path.exists():
        if time.monotonic() > deadline:
            raise TimeoutError(f"{path} did not appear in {seconds} s")
        time.sleep(0.1)


@contextlib.contextmanager
def scheduler_with_two_workers(folder):
    """A Dask scheduler on this machine with two single-threaded worker processes, the way a
    user starts one (python -m dask scheduler / worker); yields the scheduler file's path and the
    scheduler's address, and stops them all on leaving."""
    scheduler_file = folder / "scheduler.json"
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    processes = [
        subprocess.Popen(
            [sys.executable, "-m", "dask", "scheduler", "--host", "127.0.0.1",
             "--port", "0", "--no-dashboard", "--scheduler-file", str(scheduler_file)],
            **quiet,
        )
    ]
    try:
        wait_for(scheduler_file, 60)
        for _ in range(2):
            processes.append(subprocess.Popen(
                [sys.executable, "-m", "dask", "worker", "--scheduler-file",
                 str(scheduler_file), "--nthreads", "1", "--no-dashboard",
                 "--local-directory", str(folder)],
                **quiet,
            ))
        address = json.loads(scheduler_file.read_text())["address"]
        yield scheduler_file, address
    finally:
        for p in reversed(processes):
            p.terminate()
        for p in processes:
            p.wait(timeout=30)
