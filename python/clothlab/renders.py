"""clothlab.render: a frame of the headless renderer (EGL) as a numpy image."""
from clothlab import _clothlab

_VIEW_OPTIONS = ("color_by", "colormap", "force_source", "arrows")


def render(scene, frames=1, mode=3, size=(640, 360), fps=30.0, **view):
    """Renders `frames` frames of `scene` as `clothlab render` does (frame 0 the initial state,
    each later one 1 / fps s more) and returns the last as a (height, width, 3) uint8 array.

    mode: the display mode 1-9 (the window's keys). size: (width, height) in pixels.
    view: the scientific views `clothlab render` has options for: color_by ("force", "speed",
    "strain", "height"), colormap ("viridis", "magma", "turbo", "coolwarm"), force_source
    ("total", "springs", "gravity", "drag", "wind") and arrows (a list of "force", "normals").
    """
    unknown = sorted(set(view) - set(_VIEW_OPTIONS))
    if unknown:
        raise TypeError(f"clothlab.render: unknown view option(s) {unknown} ({_VIEW_OPTIONS})")
    width, height = size
    arrows = view.get("arrows", ())
    if isinstance(arrows, str):
        arrows = [arrows]
    return _clothlab._render(
        scene,
        int(frames),
        (int(width), int(height)),
        float(fps),
        int(mode),
        view.get("color_by"),
        view.get("colormap"),
        view.get("force_source"),
        [str(a) for a in arrows],
    )
