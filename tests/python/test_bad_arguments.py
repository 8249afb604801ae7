"""Bad arguments get a clear Python error naming what was wrong, never a crash or NaN."""
import math

import pytest

import clothlab


@pytest.fixture
def scene(small_scene_text):
    return clothlab.Scene.from_toml(small_scene_text)


def test_simulation_arguments(scene):
    sim = clothlab.Simulation(scene)
    with pytest.raises(ValueError, match="n must be >= 0"):
        sim.step(-1)
    for seconds in (-1.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="seconds must be finite and >= 0"):
            sim.advance(seconds)
    with pytest.raises(ValueError, match="radius must be > 0"):
        sim.push((0.0, 0.0, 0.01), radius=0.0)
    with pytest.raises(ValueError, match="must be finite"):
        sim.push((0.0, math.nan, 0.01))
    with pytest.raises(TypeError):
        sim.push((0.0, 0.01))  # two components
    with pytest.raises(IndexError, match="no vertex"):
        sim.vertex_index(12, 0)
    with pytest.raises(TypeError):
        clothlab.Simulation("scenes/default.toml")  # a path, not a Scene
    assert sim.steps == 0 and math.isfinite(sim.energy()["total"])


def test_trace_and_render_arguments(scene):
    with pytest.raises(ValueError, match="at least 1"):
        clothlab.trace(scene, 0.0)
    with pytest.raises(ValueError, match="every must be >= 1"):
        clothlab.trace(scene, 0.01, every=0)
    with pytest.raises(ValueError, match="mode must be 1 to 9"):
        clothlab.render(scene, mode=12)
    with pytest.raises(ValueError, match="size must be"):
        clothlab.render(scene, size=(0, 100))
    with pytest.raises(ValueError, match="frames must be >= 1"):
        clothlab.render(scene, frames=0)


def test_get_of_an_unknown_key_names_it(scene):
    with pytest.raises(clothlab.SceneError, match="solver.colour: unknown key"):
        scene.get("solver.colour")
    assert scene.get("springs.preset") is not None  # a key without a value in the file
