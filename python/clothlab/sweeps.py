"""clothlab.sweep: every combination of a parameter grid run as one task, on this machine or on a
Dask cluster. A task carries the scene's text, the case's parameters and the measure function;
its result is a row of numbers or an error text. No solver state crosses the network.
"""
import itertools
import time

import pandas

from clothlab._clothlab import Simulation
from clothlab.cluster import local_client


def default_measure(sim):
    """Energy (J) and the largest spring strain at the end of the run."""
    energy = sim.energy()
    per_spring, _ = sim.strain()
    largest = float(abs(per_spring).max()) if len(per_spring) else 0.0
    return {
        "energy": energy["total"],
        "kinetic_energy": energy["kinetic"],
        "elastic_energy": energy["elastic"],
        "max_strain": largest,
    }


def run_case(scene, params, duration, measure=None, threads=1):
    """One case: `scene` with each key.path of `params` set, advanced `duration` seconds, then
    measured. Returns a dict: the parameters, the measures, wall_seconds and error (None when the
    case ran; else the error's type and text, e.g. a SceneError or DivergenceError, and no
    measures). Never raises for a bad case (Ctrl-C still stops it). `threads`: solver.threads for a case whose params do not set it (the bits are the
    same on any thread count; 1 lets one worker per core run without oversubscription).
    """
    row = dict(params)
    measure = measure or default_measure
    start = time.perf_counter()
    try:
        case = scene.copy()
        settings = {} if threads is None else {"solver.threads": int(threads)}
        settings.update(params)  # a grid's own solver.threads wins
        case.update(settings)  # the scene read once for all of them
        sim = Simulation(case)
        sim.advance(duration)
        measured = measure(sim)
        row.update({str(k): float(v) for k, v in measured.items()})
        row["error"] = None
    except Exception as error:  # a bad value, a divergence, a failing measure: this row only
        row["error"] = f"{type(error).__name__}: {error}"
    row["wall_seconds"] = time.perf_counter() - start
    return row


def cases(grid):
    """The combinations of `grid` (key.path -> list of values), the last key varying fastest."""
    keys = list(grid)
    return [dict(zip(keys, combo)) for combo in itertools.product(*(list(grid[k]) for k in keys))]


def sweep(scene, grid, duration, measure=None, client=None, threads=1):
    """Runs every combination of `grid` for `duration` seconds and returns one DataFrame row per
    combination, in grid order: its parameters, its measures (`measure(sim)` -> dict of numbers;
    default energy and largest strain), wall_seconds and error (None, or the error text of a case
    that failed: a bad value, a divergence; its measures are NaN). No case is lost and none stops
    the sweep.

    client: a dask.distributed.Client (its cluster runs the cases); None starts a LocalCluster of
    one single-threaded worker process per core for this call; "serial" runs them here, one after
    the other. The rows equal serial runs' bit for bit (wall_seconds aside).
    """
    todo = cases(grid)
    if client == "serial":
        rows = [run_case(scene, c, duration, measure, threads) for c in todo]
    elif client is None:
        with local_client() as own:
            rows = _run_on(own, scene, todo, duration, measure, threads)
    else:
        rows = _run_on(client, scene, todo, duration, measure, threads)
    return _frame(rows, list(grid))


def _run_on(client, scene, todo, duration, measure, threads):
    n = len(todo)
    futures = client.map(
        run_case,
        [scene] * n,
        todo,
        [duration] * n,
        [measure] * n,
        [threads] * n,
        pure=False,
    )
    return client.gather(futures)


def _frame(rows, keys):
    measures = []
    for row in rows:
        for k in row:
            if k not in keys and k not in ("error", "wall_seconds") and k not in measures:
                measures.append(k)
    columns = keys + measures + ["wall_seconds", "error"]
    frame = pandas.DataFrame(rows, columns=columns)
    for k in measures:
        frame[k] = frame[k].astype(float)
    return frame


__all__ = ["sweep", "run_case", "cases", "default_measure"]
