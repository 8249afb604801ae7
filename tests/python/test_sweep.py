"""clothlab.sweep: every case of a grid, on a LocalCluster and on a scheduler with two worker
processes, equal to serial runs; failing cases are rows with their errors."""
import numpy
import pandas
import pytest

import clothlab
from conftest import scheduler_with_two_workers

# 2 x 2 x 2 cases: a step that diverges and a mass that is refused fail; the rest run.
GRID = {
    "cloth.mass": [0.3, -1.0],
    "springs.stiffness": [500.0, 2000.0],
    "solver.dt": [0.0005, 0.01],
}
DURATION = 0.1


def top(sim):
    return {"top_y": float(sim.positions[:, 1].max()), "time": sim.time}


def without_wall_time(frame):
    return frame.drop(columns=["wall_seconds"])


@pytest.fixture
def scene(small_scene_text):
    return clothlab.Scene.from_toml(small_scene_text)


def test_serial_sweep_has_every_case_in_grid_order_with_errors_as_rows(scene):
    frame = clothlab.sweep(scene, GRID, DURATION, client="serial")
    assert len(frame) == 8
    assert list(frame.columns[:3]) == list(GRID)
    assert list(frame["cloth.mass"]) == [0.3] * 4 + [-1.0] * 4
    bad_mass = frame["cloth.mass"] < 0
    diverged = (frame["solver.dt"] == 0.01) & ~bad_mass
    ran = ~bad_mass & ~diverged
    assert frame.error[bad_mass].str.contains("SceneError: .*cloth.mass").all()
    assert frame.error[diverged].str.contains("DivergenceError").all()
    assert frame.error[ran].isna().all()
    assert numpy.isfinite(frame.energy[ran]).all() and frame.energy[~ran].isna().all()
    assert (frame.max_strain[ran] > 0).all()
    # the measure is the simulation's own: one case run by hand gives the same numbers
    case = scene.copy()
    case.set("solver.threads", 1)
    for key, value in {"cloth.mass": 0.3, "springs.stiffness": 2000.0, "solver.dt": 0.0005}.items():
        case.set(key, value)
    sim = clothlab.Simulation(case)
    sim.advance(DURATION)
    assert frame.energy[2] == sim.energy()["total"]


def test_local_cluster_sweep_equals_serial(scene):
    serial = clothlab.sweep(scene, GRID, DURATION, measure=top, client="serial")
    # A lambda travels by value (cloudpickle); `top`, a function of this test module, would
    # travel by name, and the workers cannot import the test module.
    distributed = clothlab.sweep(
        scene,
        GRID,
        DURATION,
        measure=lambda sim: {"top_y": float(sim.positions[:, 1].max()), "time": sim.time},
    )
    pandas.testing.assert_frame_equal(
        without_wall_time(distributed), without_wall_time(serial), check_exact=True
    )


def test_scheduler_and_two_worker_processes_equal_serial(scene, tmp_path):
    from dask.distributed import Client

    with scheduler_with_two_workers(tmp_path) as (scheduler_file, _):
        with Client(scheduler_file=str(scheduler_file), timeout=60) as client:
            client.wait_for_workers(2, timeout=60)
            remote = clothlab.sweep(scene, GRID, DURATION, client=client)
            assert len(client.scheduler_info()["workers"]) == 2
    serial = clothlab.sweep(scene, GRID, DURATION, client="serial")
    pandas.testing.assert_frame_equal(
        without_wall_time(remote), without_wall_time(serial), check_exact=True
    )
