"""clothlab.trace: `clothlab trace` as a pandas DataFrame."""
import os
import shutil
import tempfile

import pandas

from clothlab import _clothlab


def trace(scene, duration, fields=None, every=None):
    """Runs `scene` for `duration` seconds and returns its trace: the columns and values of
    `clothlab trace`'s CSV (the same writer, read back by pandas).

    fields: a subset of ("position", "velocity", "force", "energy"); None keeps the scene's
    [trace] table (all four by default). every: write every N-th step (None: the scene's).
    Raises DivergenceError (no rows) when the run diverges, SceneError for a bad scene.
    """
    folder = tempfile.mkdtemp(prefix="clothlab-trace-")
    try:
        path = os.path.join(folder, "trace.csv")
        fields = None if fields is None else [str(f) for f in fields]
        _clothlab._run_trace(scene, float(duration), fields, every, path)
        # round_trip: Python's own parser, so each 17-digit number is the double the solver had
        # (pandas' default parser can miss it by an ulp)
        return pandas.read_csv(path, float_precision="round_trip")
    finally:
        shutil.rmtree(folder, ignore_errors=True)
