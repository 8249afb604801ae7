"""Shared pieces of the Python module's tests: the repository, the command line and a small
scene that runs in a fraction of a second."""
import os
import pathlib
import subprocess

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
