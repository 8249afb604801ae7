"""Simulation.intersections(): the lab's count of crossing edge/triangle pairs (docs/contact.md
section 7). The pile stress scene lands in folds with none with triangle contact on, and with
many with it off; a flat sheet has none. Simulation.contact: what triangle contact did in the
last substep (None with it off)."""
import os

import clothlab

SCENES = os.path.join(os.path.dirname(__file__), "..", "..", "scenes")


def landed_pile(contact):
    scene = clothlab.Scene.from_file(os.path.join(SCENES, "pile.toml"))
    scene.set("solver.cloth_contact", contact)
    sim = clothlab.Simulation(scene)
    assert sim.intersections() == 0  # flat as built
    sim.advance(3.5)
    return sim


def test_the_pile_does_not_pass_through_itself_with_cloth_contact():
    sim = landed_pile(True)
    assert sim.intersections() == 0
    # Its folds rest on each other: candidate pairs along them, some pushed apart every substep,
    # and the flat stretches skipped as patches.
    c = sim.contact
    assert c["candidates"] > 1000
    assert 0 < c["contacts"] < c["candidates"]
    assert 0 < c["flat_triangles"] < len(sim.triangles)
    assert c["flat_patches"] > 0
    assert not c["overflow"] and c["unresolved"] == 0


def test_the_pile_passes_through_itself_without_it():
    sim = landed_pile(False)
    assert sim.intersections() > 100
    assert sim.contact is None
