"""clothlab.Scene: the command line's parser, checks and messages."""
import pickle

import pytest

import clothlab
from conftest import run_cli


def cli_error(path, *sets):
    args = ["check", str(path)]
    for s in sets:
        args += ["--set", s]
    code, _, err = run_cli(*args)
    assert code == 2, err
    line = err.strip().splitlines()[0]
    prefix = "clothlab check: "
    assert line.startswith(prefix), line
    return line[len(prefix):]


def test_reads_a_shipped_scene_and_its_values(root):
    scene = clothlab.Scene.from_file(str(root / "scenes/default.toml"))
    assert scene.get("solver.integrator") == "symplectic_euler"
    assert scene.get("cloth.resolution") == [32, 32]
    assert scene.get("solver.newton_tolerance") == 0.01  # not in the file: the default
    scene.set("solver.integrator", "bdf2")
    scene.set("cloth.resolution", [40, 32])
    assert scene.get("solver.integrator") == "bdf2"
    assert scene.get("cloth.resolution") == [40, 32]
    assert scene.overrides == ['solver.integrator="bdf2"', "cloth.resolution=[40, 32]"]
    with pytest.raises(clothlab.SceneError, match="outside the 8 x 6 grid"):
        scene.set("cloth.resolution", [8, 6])  # the pins at i = 31 are off that grid


def test_unknown_key_is_refused_with_the_command_lines_message(root):
    path = root / "scenes/default.toml"
    scene = clothlab.Scene.from_file(str(path))
    with pytest.raises(clothlab.SceneError) as caught:
        scene.set("solver.integrater", "rk4")
    assert "solver.integrater" in str(caught.value)
    assert str(caught.value) == cli_error(path, 'solver.integrater="rk4"')
    assert isinstance(caught.value, ValueError)
    assert scene.overrides == []  # unchanged


def test_bad_value_is_refused_with_the_command_lines_message(root):
    path = root / "scenes/default.toml"
    scene = clothlab.Scene.from_file(str(path))
    with pytest.raises(clothlab.SceneError) as caught:
        scene.set("solver.dt", -1)
    assert str(caught.value) == cli_error(path, "solver.dt=-1")
    assert caught.value.key == "solver.dt"
    with pytest.raises(clothlab.SceneError, match="solver.integrator"):
        scene.set("solver.integrator", "warp_drive")


def test_missing_file_names_the_file(tmp_path):
    missing = tmp_path / "nowhere.toml"
    with pytest.raises(clothlab.SceneError) as caught:
        clothlab.Scene.from_file(str(missing))
    assert str(missing) in str(caught.value)
    assert str(caught.value) == cli_error(missing)


def test_bad_toml_text_names_line_and_key(small_scene_text):
    with pytest.raises(clothlab.SceneError) as caught:
        clothlab.Scene.from_toml(small_scene_text.replace("mass = 0.3", "mass = -0.3"))
    assert "<string>:" in str(caught.value) and "cloth.mass" in str(caught.value)
    assert caught.value.line > 0


def test_values_of_every_python_kind_round_trip(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.set("solver.dt", 0.1 + 0.2)  # 17 digits: the exact double
    assert scene.get("solver.dt") == 0.1 + 0.2
    scene.set("cloth.mass", 2)  # an int where a number goes
    assert scene.get("cloth.mass") == 2
    scene.set("forces.wind", {"velocity": (1.0, 0.0, 0.5), "gust": 0.0})
    assert scene.get("forces.wind.velocity") == [1.0, 0.0, 0.5]
    scene.set("solver.tethers", False)
    assert scene.get("solver.tethers") is False
    with pytest.raises(TypeError):
        scene.set("cloth.mass", object())


def test_scene_pickles_as_text_and_overrides(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.set("cloth.mass", 0.5)
    back = pickle.loads(pickle.dumps(scene))
    assert back.text == scene.text and back.overrides == scene.overrides
    assert back.get("cloth.mass") == 0.5


def test_update_sets_several_keys_or_none(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.update({"cloth.mass": 0.5, "solver.dt": 0.001})
    assert scene.get("cloth.mass") == 0.5 and scene.get("solver.dt") == 0.001
    with pytest.raises(clothlab.SceneError, match="solver.dt"):
        scene.update({"cloth.mass": 0.7, "solver.dt": -1.0})
    assert scene.get("cloth.mass") == 0.5  # neither was kept
    assert scene.overrides == ["cloth.mass=0.5", "solver.dt=0.001"]
