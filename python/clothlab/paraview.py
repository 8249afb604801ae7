"""clothlab.to_paraview: a simulation's frames as a ParaView time series, a .pvd collection of
.vtu meshes written by meshio (Debian's python3-meshio)."""
import os
import xml.sax.saxutils

import numpy


def _frame_mesh(sim):
    """The cloth now: its triangles with position, velocity, force and strain at the vertices."""
    import meshio  # here, so that importing clothlab (a sweep's worker) does not load it

    positions = numpy.asarray(sim.positions, dtype=numpy.float64)
    _, strain = sim.strain()
    return meshio.Mesh(
        positions,
        [("triangle", numpy.asarray(sim.triangles, dtype=numpy.int64))],
        point_data={
            "position": positions,
            "velocity": numpy.asarray(sim.velocities, dtype=numpy.float64),
            "force": numpy.asarray(sim.forces, dtype=numpy.float64),
            "strain": numpy.asarray(strain, dtype=numpy.float64),
        },
    )


def _write_complete(path, write):
    """write(temporary path), then rename: the file is complete or absent."""
    temporary = f"{path}.tmp.{os.getpid()}"
    try:
        write(temporary)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def to_paraview(sim, directory, duration=0.0, every=1.0 / 30.0, name="cloth"):
    """Writes `sim`'s current state as frame 0 and, when `duration` > 0, advances it by
    `duration` seconds writing a frame every `every` seconds; then `directory`/`name`.pvd, the
    collection ParaView opens (File > Open, then Apply; the time slider steps through the frames).
    Each frame `name`_NNNNN.vtu holds the triangles and, per vertex, position (m), velocity
    (m/s), force (N, the total) and strain (the mean engineering strain of the springs there).
    Returns the .pvd's path. A divergence stops the run (DivergenceError) and writes no .pvd.
    """
    if not every > 0.0:
        raise ValueError(f"clothlab.to_paraview: every must be > 0 (got {every})")
    os.makedirs(directory, exist_ok=True)
    frames = []

    def write_frame():
        file = f"{name}_{len(frames):05d}.vtu"
        mesh = _frame_mesh(sim)
        _write_complete(os.path.join(directory, file), lambda p: mesh.write(p, file_format="vtu"))
        frames.append((sim.time, file))

    write_frame()
    end = sim.time + duration
    while sim.time + 0.5 * sim.dt < end:
        sim.advance(min(every, end - sim.time))
        write_frame()
    pvd = os.path.join(directory, f"{name}.pvd")
    _write_complete(pvd, lambda p: _write_collection(p, frames))
    return pvd


def _write_collection(path, frames):
    lines = [
        '<?xml version="1.0"?>',
        '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
        "  <Collection>",
    ]
    for time, file in frames:
        quoted = xml.sax.saxutils.quoteattr(file)
        lines.append(f'    <DataSet timestep="{time:.17g}" group="" part="0" file={quoted}/>')
    lines += ["  </Collection>", "</VTKFile>", ""]
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
