"""clothlab.tune: the same table on a LocalCluster as serially and as the command line's CSV (the
costs, and the frontier and recommendation they decide, aside), the command line's on a Dask
scheduler the same as its serial one, and a recommendation that is the cheapest finished setting
within the tolerance."""
import pandas
import pytest

import clothlab
from conftest import run_cli, scheduler_with_two_workers

DURATION = 0.25
TOLERANCE = 0.01
TIMED = ["cost", "frontier", "recommended"]


@pytest.fixture
def scene(small_scene_text):
    return clothlab.Scene.from_toml(small_scene_text)


def test_local_cluster_equals_serial(scene):
    serial = clothlab.tune(scene, DURATION, TOLERANCE, client="serial", stop_slower=False)
    distributed = clothlab.tune(scene, DURATION, TOLERANCE, stop_slower=False)
    pandas.testing.assert_frame_equal(
        serial.drop(columns=TIMED), distributed.drop(columns=TIMED), check_exact=True
    )
    assert serial.attrs == distributed.attrs
    assert serial.family[0] == "reference" and len(serial) == 24
    assert (serial.status == "ok").all()  # nothing stopped, nothing diverged on this sheet


def test_recommendation_is_the_cheapest_within_the_tolerance(scene):
    frame = clothlab.tune(scene, DURATION, TOLERANCE, client="serial")
    candidates = frame.iloc[1:]
    within = candidates[(candidates.status == "ok") & (candidates.worst_rms <= TOLERANCE)]
    assert len(within) > 0
    assert frame.recommended.sum() == 1
    chosen = frame[frame.recommended].iloc[0]
    assert chosen.cost == within.cost.min()
    assert chosen.frontier
    # The frontier, by cost, only ever gets more accurate.
    front = frame[frame.frontier].sort_values("cost")
    assert front.worst_rms.is_monotonic_decreasing
    # worst_rms is the largest of the sample times' RMS.
    rms = [c for c in frame.columns if c.startswith("rms_")]
    assert len(rms) == len(frame.attrs["times"]) == 4
    ok = frame[frame.status == "ok"]
    assert (ok[rms].max(axis=1) == ok.worst_rms).all()
    assert (frame[frame.status != "ok"].worst_rms == float("inf")).all()


def test_errors_equal_the_command_lines(scene, small_scene_text, tmp_path):
    frame = clothlab.tune(scene, DURATION, TOLERANCE, client="serial", stop_slower=False)
    scene_file = tmp_path / "sheet.toml"
    scene_file.write_text(small_scene_text)
    out = tmp_path / "tune.csv"
    code, stdout, err = run_cli(
        "tune", str(scene_file), "--duration", repr(DURATION), "--tolerance", repr(TOLERANCE),
        "--threads", "1", "--quiet", "--out", str(out),
    )
    assert code == 0, err
    assert "within 10 mm RMS up to 0.25 s" in stdout
    csv = read_table(out)
    times = frame.attrs["times"]
    compared = 0
    for _, row in frame.iloc[1:].iterrows():
        cli = csv[(csv.setting == row.setting) & (csv.status == "ok")]
        if len(cli) != len(times):  # stopped by the command line's clock
            continue
        for k, t in enumerate(times):
            assert cli["rms error (m)"].iloc[k] == row[f"rms_{t:.3g}"], row.setting
        compared += 1
    assert compared >= 10


def read_table(path):
    """tune's CSV with exact doubles; a setting its clock stopped has "-" for the numbers it did
    not reach, read as NaN so that the columns stay numbers (as text they equal no float)."""
    return pandas.read_csv(path, float_precision="round_trip", na_values=["-"])


def test_command_line_on_a_scheduler_equals_its_serial_table(small_scene_text, tmp_path):
    scene_file = tmp_path / "sheet.toml"
    scene_file.write_text(small_scene_text)
    args = ["tune", str(scene_file), "--duration", repr(DURATION), "--tolerance",
            repr(TOLERANCE), "--threads", "1"]
    remote_csv, serial_csv = tmp_path / "remote.csv", tmp_path / "serial.csv"
    with scheduler_with_two_workers(tmp_path) as (_, address):
        code, stdout, err = run_cli(*args, "--scheduler", address, "--out", str(remote_csv))
    assert code == 0, err
    assert f"tune: on the scheduler at {address}" in err and "tune: [23/23]" in err
    assert "within 10 mm RMS up to 0.25 s" in stdout
    assert remote_csv.with_suffix(".png").stat().st_size > 10000
    code, _, err = run_cli(*args, "--quiet", "--out", str(serial_csv))
    assert code == 0, err
    remote, serial = read_table(remote_csv), read_table(serial_csv)
    exact = ["rms error (m)", "max error (m)", "energy drift (J)"]
    reference = remote.family == "reference"
    assert (remote[reference][exact].values == serial[serial.family == "reference"][exact].values).all()
    compared = 0
    for setting in remote.setting.unique():
        a = remote[(remote.setting == setting) & (remote.status == "ok")]
        b = serial[(serial.setting == setting) & (serial.status == "ok")]
        if len(a) != 4 or len(b) != 4 or setting == remote.setting[0]:
            continue  # stopped by one side's clock, or the reference
        assert (a[exact].values == b[exact].values).all(), setting
        compared += 1
    assert compared >= 10


def test_simulation_takes_the_tolerances_setting_from_the_cache(scene, tmp_path, monkeypatch):
    monkeypatch.setenv("CLOTHLAB_CACHE_DIR", str(tmp_path / "cache"))
    scene.set("solver.tolerance", 0.02)
    first = clothlab.Simulation(scene)
    assert "the cheapest of the tune within 20 mm to 1 s" in first.backend_note
    assert "from the cache" not in first.backend_note
    assert len(list((tmp_path / "cache").glob("tune-*.toml"))) == 1
    scene.set("solver.tolerance", 0.005)  # another tolerance reads the same entry
    second = clothlab.Simulation(scene)
    assert "within 5 mm to 1 s" in second.backend_note
    assert second.backend_note.endswith("(from the cache)")
    scene.set("solver.tolerance", 1e-12)
    with pytest.raises(clothlab.SceneError, match="below the reference's own error"):
        clothlab.Simulation(scene)
