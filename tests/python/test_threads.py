"""Two simulations in two Python threads run side by side: stepping releases the GIL. Whether
they also finish sooner than one after the other is a matter of timing, which the benchmarks
measure, not these tests."""
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


def test_two_simulations_in_two_threads_run_side_by_side(small_scene_text):
    """While two simulations advance in two threads, this thread keeps running and sees their
    step counts part-way: with the GIL held through a step it could not run until a call
    returned. Each ends where the same simulation ends alone."""
    if len(os.sched_getaffinity(0)) < 2:
        pytest.skip("one core: two threads cannot run side by side")
    seconds = 2.0
    alone = make_sim(small_scene_text)
    alone.advance(seconds)
    c, d = make_sim(small_scene_text), make_sim(small_scene_text)
    threads = [threading.Thread(target=s.advance, args=(seconds,)) for s in (c, d)]
    for t in threads:
        t.start()
    seen = set()
    while any(t.is_alive() for t in threads):
        seen.add((c.steps, d.steps))
    for t in threads:
        t.join()
    assert (c.positions == alone.positions).all() and (d.positions == alone.positions).all()
    part_way = {s for s in seen if 0 < s[0] < alone.steps or 0 < s[1] < alone.steps}
    assert len(part_way) >= 10, sorted(seen)


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
