"""The errors clothlab raises. Both pickle, so a sweep's worker can report them."""


class SceneError(ValueError):
    """A bad scene file, key or value: the message `clothlab` prints before exiting with 2."""

    def __init__(self, message, file="", line=0, key=""):
        super().__init__(message)
        self.file = file
        self.line = line
        self.key = key

    def __reduce__(self):
        return (type(self), (str(self), self.file, self.line, self.key))


class DivergenceError(RuntimeError):
    """The solver's divergence monitor stopped the run (a non-finite value or runaway energy)."""

    def __init__(self, message, step=0, time=0.0, vertex=(0, 0, 0), quantity=""):
        super().__init__(message)
        self.step = step  # the step after which it was detected (1-based)
        self.time = time  # s
        self.vertex = tuple(vertex)  # (cloth, i, j) of the offending vertex
        self.quantity = quantity  # e.g. "velocity.y = nan"

    def __reduce__(self):
        return (type(self), (str(self), self.step, self.time, self.vertex, self.quantity))
