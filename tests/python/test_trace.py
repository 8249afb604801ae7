"""clothlab.trace: the command line's CSV as a DataFrame."""
import pandas
import pytest

import clothlab
from conftest import cli_trace


def test_trace_frame_equals_the_command_lines_csv(tmp_path, small_scene_text):
    scene_file, expected = cli_trace(tmp_path, small_scene_text, 0.1)
    frame = clothlab.trace(clothlab.Scene.from_file(str(scene_file)), 0.1)
    pandas.testing.assert_frame_equal(frame, expected, check_exact=True)
    assert list(frame.columns[:4]) == ["step", "time", "vertex_i", "vertex_j"]


def test_fields_and_interval_choose_columns_and_rows(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    frame = clothlab.trace(scene, 0.05, fields=["position", "energy"], every=25)
    assert list(frame.columns) == [
        "step", "time", "vertex_i", "vertex_j", "px", "py", "pz",
        "kinetic", "elastic", "gravity", "total",
    ]
    assert sorted(set(frame.step)) == [0, 25, 50, 75, 100]
    with pytest.raises(ValueError, match="unknown field"):
        clothlab.trace(scene, 0.05, fields=["colour"])


def test_a_diverging_trace_raises_and_writes_nothing(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.set("solver.dt", 0.01)
    with pytest.raises(clothlab.DivergenceError):
        clothlab.trace(scene, 2.0)
