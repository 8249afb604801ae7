"""ClothLab for Python: scenes, simulations, traces and parameter sweeps.

    import clothlab
    scene = clothlab.Scene.from_file("scenes/default.toml")
    scene.set("solver.integrator", "bdf2")
    sim = clothlab.Simulation(scene)
    sim.advance(0.5)
    sim.positions          # numpy (vertices, 3), a copy in the solver's precision

docs/python.md has the whole API.
"""
import os

# libgomp reads its wait policy when it loads, which is when the extension below is imported:
# threads that sleep at barriers after a short spin, as every ClothLab program runs
# (sim/core/passive_openmp.hpp). A policy the user set is kept.
if "OMP_WAIT_POLICY" not in os.environ:
    os.environ["OMP_WAIT_POLICY"] = "passive"
    os.environ.setdefault("GOMP_SPINCOUNT", "1000")

from clothlab._clothlab import Scene, Simulation  # noqa: E402
from clothlab.errors import DivergenceError, SceneError  # noqa: E402
from clothlab.traces import trace  # noqa: E402
from clothlab.sweeps import run_case, sweep  # noqa: E402
from clothlab.tuning import tune  # noqa: E402
from clothlab.renders import render  # noqa: E402
from clothlab.paraview import to_paraview  # noqa: E402

__all__ = [
    "Scene",
    "Simulation",
    "SceneError",
    "DivergenceError",
    "trace",
    "sweep",
    "run_case",
    "tune",
    "render",
    "to_paraview",
]
