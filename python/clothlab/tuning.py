"""clothlab.tune (this module: clothlab.tuning): run time against error on a scene (docs/tuning.md), the same measurement as
`clothlab tune`, with its runs as tasks on this machine or on a Dask cluster. The two reference
runs go first, side by side; every setting of the ladder starts as soon as the coarser one has
ended (a setting is stopped once it takes twice that run's time, the finer run's expected time)
and returns its positions at the sample times, measured here against the finer run. A task
carries the scene's text and the setting's --set lines; the C++ code (tune/tune.hpp) runs and
measures, so the table equals the command line's, cost aside.
"""
import math

import pandas

from clothlab import _clothlab
from clothlab.cluster import local_client


def _run(scene, setting, times, threads, wall_limit):
    return _clothlab.tune_run(scene, setting, times, threads, wall_limit)


def _checked(setting, run):
    if run["failure"]:
        raise RuntimeError(f"the reference ({setting['label']}) {run['failure']}")
    return run


def _runs_serial(scene, settings, times, threads, stop_slower):
    coarse = _checked(settings["coarse"], _run(scene, settings["coarse"], times, threads, 0.0))
    fine = _checked(settings["reference"], _run(scene, settings["reference"], times, threads, 0.0))
    limit = 2.0 * coarse["wall"] if stop_slower else 0.0
    runs = [_run(scene, s, times, threads, limit) for s in settings["ladder"]]
    return coarse, fine, runs


def _runs_on(client, scene, settings, times, threads, stop_slower, progress=None):
    # The finer reference first, so that it starts first; the ladder once the coarser one has
    # said how long a setting may take.
    fine = client.submit(_run, scene, settings["reference"], times, threads, 0.0, pure=False)
    coarse = client.submit(_run, scene, settings["coarse"], times, threads, 0.0, pure=False)
    coarse = _checked(settings["coarse"], coarse.result())
    limit = 2.0 * coarse["wall"] if stop_slower else 0.0
    n = len(settings["ladder"])
    runs = client.map(
        _run, [scene] * n, settings["ladder"], [times] * n, [threads] * n, [limit] * n, pure=False
    )
    if progress:
        from dask.distributed import as_completed

        labels = {f.key: s["label"] for f, s in zip(runs, settings["ladder"])}
        for done, future in enumerate(as_completed(runs), 1):
            progress(f"[{done}/{n}] {labels[future.key]}: {future.result()['failure'] or 'ok'}")
    return coarse, _checked(settings["reference"], fine.result()), client.gather(runs)


def _measure(scene, duration, client, threads, samples, stop_slower, progress=None):
    """The sample times, the settings, the two reference runs and the ladder's rows."""
    times = _clothlab.tune_times(duration, samples)
    settings = _clothlab.tune_settings(scene, threads)
    if client == "serial":
        coarse, fine, runs = _runs_serial(scene, settings, times, threads, stop_slower)
    else:
        coarse, fine, runs = _runs_on(
            client, scene, settings, times, threads, stop_slower, progress
        )
    rows = [_clothlab.tune_row(s, r, fine, times) for s, r in zip(settings["ladder"], runs)]
    return times, settings, coarse, fine, rows


def write_result(path, scene, duration, client, threads=1, samples=4, progress=None):
    """Runs the tune of `scene` on `client` and writes the whole table to `path` (TOML, exact
    numbers) for the command line to read back (`clothlab tune --scheduler`,
    tune/result_file.hpp)."""
    times, settings, coarse, fine, rows = _measure(
        scene, duration, client, threads, samples, True, progress
    )
    self_error = _clothlab.tune_distance(fine["positions"], coarse["positions"])
    _clothlab.tune_write_result(
        path, times, settings["reference"], self_error, fine["wall"] / times[-1],
        2.0 * coarse["wall"], rows,
    )


def _frame(rows, reference, self_error, times, picked):
    records = []
    cost = reference["wall"] / times[-1]
    ref_row = dict(reference["setting"], rms=[e[0] for e in self_error], status="ok")
    ref_row.update(max=[e[1] for e in self_error], energy_drift=0.0, cost=cost)
    for i, row in enumerate([ref_row] + rows):
        record = {"setting": row["label"], "family": row["family"], "cost": row["cost"]}
        finished = row["status"] == "ok"
        record["worst_rms"] = max(row["rms"]) if finished and row["rms"] else math.inf
        for k, t in enumerate(times):
            record[f"rms_{t:.3g}"] = row["rms"][k] if k < len(row["rms"]) else math.nan
        record["max_error"] = row["max"][-1] if row["max"] else math.nan
        record["energy_drift"] = row["energy_drift"] if row["rms"] else math.nan
        record["status"] = row["status"]
        record["frontier"] = i > 0 and (i - 1) in picked["frontier"]
        record["recommended"] = i > 0 and picked["chosen"] == i - 1
        record["set"] = " ".join(row["overrides"])
        records.append(record)
    return pandas.DataFrame(records)


def tune(scene, duration=1.0, tolerance=None, client=None, threads=1, samples=4, stop_slower=True):
    """Measures every setting of the ladder on `scene` against its reference up to `duration`
    seconds and returns a DataFrame, the reference first: setting, family, cost (wall seconds per
    simulated second), worst_rms (m, the largest RMS over the sample times), rms_<t> (m, at each
    sample time t), max_error (m, at the last), energy_drift (J, against the reference at the last
    time reached), status ("ok", or why the setting has no result), frontier, recommended (the
    cheapest within `tolerance` m, if given) and set (its --set lines). attrs["times"] holds the
    sample times, attrs["reference_error"] the reference's own error bound at each (m).

    client: a dask.distributed.Client; None starts a LocalCluster of one single-threaded worker
    per core for this call; "serial" runs here. threads: solver threads of every run.
    stop_slower: stop a setting once it takes longer than the reference is expected to (as the
    command line does); False runs every setting to the end, so the table does not depend on
    timing.
    """
    if client is None:
        with local_client() as own:
            return tune(scene, duration, tolerance, own, threads, samples, stop_slower)
    times, settings, coarse, fine, rows = _measure(
        scene, duration, client, threads, samples, stop_slower
    )
    self_error = _clothlab.tune_distance(fine["positions"], coarse["positions"])
    picked = _clothlab.tune_pick(rows, tolerance)
    reference = dict(fine, setting=settings["reference"])
    frame = _frame(rows, reference, self_error, times, picked)
    frame.attrs["times"] = list(times)
    frame.attrs["reference_error"] = [e[0] for e in self_error]
    return frame


__all__ = ["tune"]
