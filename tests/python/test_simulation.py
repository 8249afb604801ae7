"""clothlab.Simulation: the same steps as `clothlab trace`, fields as numpy arrays, divergence
and Ctrl-C, pushes, drops and resets."""
import os
import signal
import threading
import time

import numpy
import pytest

import clothlab
from conftest import cli_trace


def test_positions_equal_the_command_lines_trace_bit_for_bit(tmp_path, small_scene_text):
    scene_file, csv = cli_trace(tmp_path, small_scene_text, 0.25)
    sim = clothlab.Simulation(clothlab.Scene.from_file(str(scene_file)))
    sim.advance(0.125)
    sim.advance(0.125)  # two calls take the steps one takes
    assert sim.steps == csv["step"].iloc[-1] == 500
    positions = sim.positions
    assert positions.dtype == numpy.float64 and positions.shape == (144, 3)
    for i, j in [(6, 11), (0, 11)]:
        last = csv[(csv.vertex_i == i) & (csv.vertex_j == j)].iloc[-1]
        v = sim.vertex_index(i, j)
        assert list(positions[v]) == [last.px, last.py, last.pz]  # exact: 17 digits in the CSV
        assert list(sim.velocities[v]) == [last.vx, last.vy, last.vz]
        assert list(sim.forces[v]) == [last.fx, last.fy, last.fz]
    energy = sim.energy()
    assert energy["total"] == csv["total"].iloc[-1]
    assert energy["total"] == pytest.approx(
        energy["kinetic"] + energy["elastic"] + energy["gravity"], abs=1e-12
    )


def test_float_scenes_give_float32_copies(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.set("solver.precision", "float")
    sim = clothlab.Simulation(scene)
    sim.step(10)
    p = sim.positions
    assert p.dtype == numpy.float32 and p.shape == (sim.vertex_count, 3)
    p[:] = 0.0  # a copy: the solver keeps its state
    assert numpy.abs(sim.positions).max() > 0.1


def test_push_adds_exactly_its_momentum(small_scene_text):
    sim = clothlab.Simulation(clothlab.Scene.from_toml(small_scene_text))
    sim.step(20)
    masses = sim.masses[:, None]
    before = (masses * sim.velocities).sum(axis=0)
    sim.push((0.0, 0.0, 0.02))
    after = (masses * sim.velocities).sum(axis=0)
    assert after - before == pytest.approx([0.0, 0.0, 0.02], abs=1e-12)
    assert sim.pinned.sum() == 2


def test_drop_lets_the_pins_go_and_reset_holds_them_again(small_scene_text):
    sim = clothlab.Simulation(clothlab.Scene.from_toml(small_scene_text))
    corner = sim.vertex_index(0, 0)
    start = sim.positions[corner].copy()
    sim.drop()
    sim.advance(0.1)
    fallen = start[1] - sim.positions[corner][1]
    assert fallen > 0.5 * 9.81 * 0.1**2 * 0.5  # in free fall, slowed by the cloth
    sim.reset()
    assert sim.time == 0.0
    assert (sim.positions == sim.rest_positions).all()
    sim.advance(0.1)
    assert (sim.positions[corner] == start).all()


def test_an_exploding_scene_raises_divergence_with_where_and_when(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.set("solver.dt", 0.01)  # 20x the step: symplectic Euler blows up
    sim = clothlab.Simulation(scene)
    with pytest.raises(clothlab.DivergenceError) as caught:
        sim.advance(2.0)
    e = caught.value
    assert e.step > 0 and e.time == pytest.approx(e.step * 0.01)
    assert len(e.vertex) == 3 and e.quantity
    with pytest.raises(clothlab.DivergenceError):  # it stays stopped
        sim.step()


def test_ctrl_c_stops_a_long_advance_within_a_frame(small_scene_text):
    sim = clothlab.Simulation(clothlab.Scene.from_toml(small_scene_text))
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        sim.advance(3600.0)
    assert time.perf_counter() - start < 5.0
    assert 0.0 < sim.time < 3600.0


def test_fields_have_their_shapes_and_sources(small_scene_text):
    sim = clothlab.Simulation(clothlab.Scene.from_toml(small_scene_text))
    sim.step(50)
    n = sim.vertex_count
    total = sim.force("total")
    parts = sum(sim.force(s) for s in ("springs", "gravity", "drag", "wind"))
    free = ~sim.pinned
    assert total.shape == (n, 3)
    numpy.testing.assert_allclose(total[free], parts[free], atol=1e-12)
    assert sim.force("gravity")[free][:, 1] == pytest.approx(-9.81 * sim.masses[free])
    per_spring, per_vertex = sim.strain()
    assert per_spring.shape == (len(sim.springs),) and per_vertex.shape == (n,)
    assert sim.triangles.shape == (2 * 11 * 11, 3)
    with pytest.raises(ValueError, match="unknown source"):
        sim.force("magnetism")


def test_transform_feedback_steps_as_the_cpu_and_refuses_verlet(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.update({"solver.precision": "float", "solver.integrator": "symplectic_euler"})
    cpu = clothlab.Simulation(scene)
    scene.set("solver.backend", "transform_feedback")
    tf = clothlab.Simulation(scene)
    assert (cpu.backend, tf.backend, tf.backend_note) == ("CPU", "GPU transform feedback", "")
    cpu.step(200)
    tf.step(200)
    assert numpy.abs(tf.positions - cpu.positions).max() < 1e-5
    assert numpy.abs(tf.positions - clothlab.Simulation(scene).positions).max() > 1e-3
    with pytest.raises(clothlab.SceneError, match="solver.integrator"):
        scene.set("solver.integrator", "verlet")
