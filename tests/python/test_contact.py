"""Simulation.intersections(): the lab's count of crossing edge/triangle pairs (docs/contact.md
section 7). The pile stress scene lands in folds with none with triangle contact on, and with
many with it off; a flat sheet has none."""
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
    assert landed_pile(True).intersections() == 0


def test_the_pile_passes_through_itself_without_it():
    assert landed_pile(False).intersections() > 100
