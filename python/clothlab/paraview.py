"""clothlab.to_paraview: a simulation's frames, or a trace's rows, as a ParaView time series: a
.pvd collection of .vtu files written by meshio (Debian's python3-meshio)."""
import os
import xml.sax.saxutils

import numpy


def _mesh(points, cells, point_data):
    import meshio  # here, so that importing clothlab (a sweep's worker) does not load it

    return meshio.Mesh(numpy.asarray(points, dtype=numpy.float64), cells, point_data=point_data)


def _cloth_mesh(sim):
    """The cloth now: its triangles with position, velocity, force and strain at the vertices."""
    positions = numpy.asarray(sim.positions, dtype=numpy.float64)
    _, strain = sim.strain()
    return _mesh(
        positions,
        [("triangle", numpy.asarray(sim.triangles, dtype=numpy.int64))],
        {
            "position": positions,
            "velocity": numpy.asarray(sim.velocities, dtype=numpy.float64),
            "force": numpy.asarray(sim.forces, dtype=numpy.float64),
            "strain": numpy.asarray(strain, dtype=numpy.float64),
        },
    )


def _trace_mesh(rows):
    """One step of a trace: its vertices as points, with the fields the trace holds."""
    positions = rows[["px", "py", "pz"]].to_numpy(dtype=numpy.float64)
    data = {"position": positions}
    for name, columns in (("velocity", ["vx", "vy", "vz"]), ("force", ["fx", "fy", "fz"])):
        if set(columns) <= set(rows.columns):
            data[name] = rows[columns].to_numpy(dtype=numpy.float64)
    for column in ("cloth", "vertex_i", "vertex_j"):
        if column in rows.columns:
            data[column] = rows[column].to_numpy()
    cells = [("vertex", numpy.arange(len(rows), dtype=numpy.int64).reshape(-1, 1))]
    return _mesh(positions, cells, data)


def _write_complete(path, write):
    """write(temporary path), then rename: the file is complete or absent."""
    temporary = f"{path}.tmp.{os.getpid()}"
    try:
        write(temporary)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


class _Series:
    """The frames written so far into `directory`, and the collection that lists them."""

    def __init__(self, directory, name):
        os.makedirs(directory, exist_ok=True)
        self.directory, self.name, self.frames = directory, name, []

    def add(self, time, mesh):
        file = f"{self.name}_{len(self.frames):05d}.vtu"
        path = os.path.join(self.directory, file)
        _write_complete(path, lambda p: mesh.write(p, file_format="vtu"))
        self.frames.append((time, file))

    def finish(self):
        pvd = os.path.join(self.directory, f"{self.name}.pvd")
        _write_complete(pvd, lambda p: _write_collection(p, self.frames))
        return pvd


def to_paraview(trace_or_simulation, directory, duration=0.0, every=1.0 / 30.0, name="cloth"):
    """Writes a ParaView time series into `directory` and returns its .pvd, the collection
    ParaView opens (File > Open, then Apply; the time slider steps through the frames).

    A Simulation: its current state as frame 0 and, when `duration` > 0, a frame every `every`
    seconds while it advances by `duration`. Each frame `name`_NNNNN.vtu is the cloth's
    triangles with, per vertex, position (m), velocity (m/s), force (N, the total) and strain
    (the mean engineering strain of the springs there). A divergence stops the run
    (DivergenceError) and writes no .pvd.

    A trace (clothlab.trace's DataFrame): one frame per written step, its traced vertices as
    points with position and the velocity, force and vertex indices the trace holds (a trace
    has no triangles). `duration` and `every` do not apply.
    """
    series = _Series(directory, name)
    if hasattr(trace_or_simulation, "groupby"):
        if not {"step", "time", "px", "py", "pz"} <= set(trace_or_simulation.columns):
            raise ValueError(
                "clothlab.to_paraview: a trace needs the step, time and position columns "
                "(clothlab.trace with 'position' among its fields)"
            )
        for _, rows in trace_or_simulation.groupby("step", sort=True):
            series.add(float(rows["time"].iloc[0]), _trace_mesh(rows))
        return series.finish()
    if not every > 0.0:
        raise ValueError(f"clothlab.to_paraview: every must be > 0 (got {every})")
    sim = trace_or_simulation
    series.add(sim.time, _cloth_mesh(sim))
    end = sim.time + duration
    while sim.time + 0.5 * sim.dt < end:
        sim.advance(min(every, end - sim.time))
        series.add(sim.time, _cloth_mesh(sim))
    return series.finish()


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
