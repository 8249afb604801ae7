"""clothlab.render (the headless renderer into numpy) and clothlab.to_paraview (a .pvd of .vtu
frames through meshio)."""
import os
import xml.etree.ElementTree as ElementTree

import meshio
import numpy
import pytest

import clothlab


def test_render_shows_the_cloth_over_the_background(small_scene_text):
    scene = clothlab.Scene.from_toml(small_scene_text)
    scene.set("solver.precision", "float")
    image = clothlab.render(scene, frames=3, mode=2, size=(160, 120))
    assert image.shape == (120, 160, 3) and image.dtype == numpy.uint8
    # mode 2 colours the cloth by its normals, over a plain background: the cloth's pixels are
    # those unlike the corner's, and they cover a good part of the middle of the picture
    background = image[2, 2].astype(int)
    differs = numpy.abs(image.astype(int) - background).sum(axis=2) > 30
    middle = differs[30:90, 40:120]
    assert 0.2 < middle.mean() <= 1.0, middle.mean()
    assert differs[:5].mean() < 0.5  # the top rows stay mostly background
    with pytest.raises(ValueError, match="color_by"):
        clothlab.render(scene, color_by="temperature")
    with pytest.raises(TypeError, match="unknown view option"):
        clothlab.render(scene, colour="red")


def test_paraview_export_round_trips_through_meshio(small_scene_text, tmp_path):
    sim = clothlab.Simulation(clothlab.Scene.from_toml(small_scene_text))
    sim.step(40)
    pvd = clothlab.to_paraview(sim, str(tmp_path), duration=0.05, every=0.025)
    collection = ElementTree.parse(pvd).getroot().find("Collection")
    entries = [(float(d.get("timestep")), d.get("file")) for d in collection]
    assert [t for t, _ in entries] == pytest.approx([0.02, 0.045, 0.07])
    last = meshio.read(os.path.join(tmp_path, entries[-1][1]))
    numpy.testing.assert_array_equal(last.points, sim.positions)
    numpy.testing.assert_array_equal(last.cells_dict["triangle"], sim.triangles)
    numpy.testing.assert_array_equal(last.point_data["velocity"], sim.velocities)
    numpy.testing.assert_array_equal(last.point_data["force"], sim.forces)
    numpy.testing.assert_array_equal(last.point_data["strain"], sim.strain()[1])
    assert not [f for f in os.listdir(tmp_path) if ".tmp." in f]


def test_a_traces_rows_export_as_points_per_step(small_scene_text, tmp_path):
    frame = clothlab.trace(clothlab.Scene.from_toml(small_scene_text), 0.02, every=20)
    pvd = clothlab.to_paraview(frame, str(tmp_path / "trace"), name="traced")
    collection = ElementTree.parse(pvd).getroot().find("Collection")
    files = [d.get("file") for d in collection]
    assert len(files) == frame.step.nunique() == 3  # steps 0, 20, 40
    last = meshio.read(str(tmp_path / "trace" / files[-1]))
    rows = frame[frame.step == frame.step.max()]
    numpy.testing.assert_array_equal(last.points, rows[["px", "py", "pz"]].to_numpy())
    numpy.testing.assert_array_equal(last.point_data["force"], rows[["fx", "fy", "fz"]].to_numpy())
    numpy.testing.assert_array_equal(last.point_data["vertex_i"], rows.vertex_i.to_numpy())
    with pytest.raises(ValueError, match="position"):
        clothlab.to_paraview(frame.drop(columns=["px"]), str(tmp_path / "bad"))
