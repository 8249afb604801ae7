"""Two simulations in two Python threads run side by side: stepping releases the GIL. Run alone
(RUN_SERIAL): it compares wall times, which another test beside it would distort."""
import os
import threading
import time

import pytest

import clothlab


def make_sim(text):
    scene = clothlab.Scene.from_toml(text)
    scene.set("cloth.resolution", [40, 40])
    scene.set("cloth.pins", [[0, 0], [39, 0]])
    scene.set("trace.vertices", [[20, 39]])
    scene.set("solver.dt", "auto")  # the finer grid's stable step
    return clothlab.Simulation(scene)


def test_two_simulations_in_two_threads_beat_one_after_the_other(small_scene_text):
    if len(os.sched_getaffinity(0)) < 2:
        pytest.skip("one core: two threads cannot run side by side")
    seconds = 2.0
    a, b = make_sim(small_scene_text), make_sim(small_scene_text)
    start = time.perf_counter()
    a.advance(seconds)
    b.advance(seconds)
    serial = time.perf_counter() - start
    c, d = make_sim(small_scene_text), make_sim(small_scene_text)
    threads = [threading.Thread(target=s.advance, args=(seconds,)) for s in (c, d)]
    start = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    parallel = time.perf_counter() - start
    assert (c.positions == a.positions).all() and (d.positions == b.positions).all()
    # Two cores: about half; with the GIL held it would be the same as serial.
    assert parallel < 0.8 * serial, (parallel, serial)


def test_a_simulation_stepping_in_one_thread_refuses_another(small_scene_text):
    sim = make_sim(small_scene_text)
    runner = threading.Thread(target=sim.advance, args=(3.0,))
    runner.start()
    while sim.steps == 0:
        time.sleep(0.001)
    try:
        with pytest.raises(RuntimeError, match="busy stepping in another thread"):
            sim.positions
        with pytest.raises(RuntimeError, match="busy stepping in another thread"):
            sim.step()
    finally:
        runner.join()
    assert sim.time == pytest.approx(3.0)
    assert sim.positions.shape == (1600, 3)  # free again
