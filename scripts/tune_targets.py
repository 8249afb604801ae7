"""Checks `clothlab tune`'s recommendations on three kinds of scene (docs/tuning.md, "Measured"):
each scene is tuned to T = 1 s, and for tolerances of 60, 20 and 5 mm the recommended setting is
run again on its own beside the reference, its error measured at the sample times, and its cost
timed again against every setting within the tolerance that tune found at most twice as dear
(the best of two timed runs each). Prints a Markdown table.

    scripts/python scripts/tune_targets.py [--threads 2] [--only default,dance,sheet128]
"""
import argparse
import pathlib
import time

import numpy

import clothlab

ROOT = pathlib.Path(__file__).resolve().parents[1]
TOLERANCES = [0.06, 0.02, 0.005]


def scenes():
    sheet = clothlab.Scene.from_file(str(ROOT / "scenes/hanging_sheet.toml"))
    sheet.update({
        "cloth.resolution": [128, 128],
        "cloth.pins": [[0, 0], [127, 0]],
        "trace.vertices": [[64, 127]],
        "springs.stiffness": 1e4,
    })
    return {
        "default": clothlab.Scene.from_file(str(ROOT / "scenes/default.toml")),
        "dance": clothlab.Scene.from_file(str(ROOT / "scenes/dance.toml")),
        "sheet128": sheet,
    }


def with_setting(scene, row, threads):
    case = scene.copy()
    case.update({"solver.backend": "cpu", "solver.threads": threads})
    case.override(row["set"].split())
    return case


def sampled(case, times):
    """Positions at each time and the wall time stepping took."""
    sim = clothlab.Simulation(case)
    out, wall = [], 0.0
    for t in times:
        start = time.perf_counter()
        sim.advance(t - sim.time)
        wall += time.perf_counter() - start
        out.append(numpy.array(sim.positions, dtype=float))
    return out, wall


def check(name, scene, threads):
    frame = clothlab.tune(scene, 1.0, client="serial", threads=threads)
    times = frame.attrs["times"]
    reference, _ = sampled(with_setting(scene, frame.iloc[0], threads), times)
    rows = []
    for tol in TOLERANCES:
        ok = frame.iloc[1:][(frame.iloc[1:].status == "ok") & (frame.iloc[1:].worst_rms <= tol)]
        if tol < max(frame.attrs["reference_error"]) or ok.empty:
            rows.append(f"| {name} | {tol * 1e3:g} | none | - | - | - |")
            continue
        chosen = ok.loc[ok.cost.idxmin()]
        positions, _ = sampled(with_setting(scene, chosen, threads), times)
        error = max(numpy.sqrt(((p - r) ** 2).sum(axis=1).mean()) for p, r in zip(positions, reference))
        costs = {}
        for _, row in ok[ok.cost <= 2.0 * chosen.cost].iterrows():
            costs[row.setting] = min(sampled(with_setting(scene, row, threads), times)[1]
                                     for _ in range(2)) / times[-1]
        ratio = costs[chosen.setting] / min(costs.values())
        rows.append(f"| {name} | {tol * 1e3:g} | {chosen.setting} | {error * 1e3:.3g} | "
                    f"{costs[chosen.setting]:.3g} | {ratio:.2f} ({len(costs)} timed) |")
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", default="default,dance,sheet128")
    args = parser.parse_args()
    print("| scene | tolerance (mm) | recommended | its error, run again (mm) | its cost (s/s) "
          "| cost / cheapest within the tolerance |")
    print("| --- | --- | --- | --- | --- | --- |")
    for name, scene in scenes().items():
        if name in args.only.split(","):
            for line in check(name, scene, args.threads):
                print(line, flush=True)


if __name__ == "__main__":
    main()
