#!/usr/bin/python3
"""Writes assets/meshes/vase.obj: a vase as a surface of revolution about +y (a closed surface
with a flat base and an open-looking lip turned inwards), the project's own mesh for OBJ
scenery (nothing is downloaded). Meant to be drawn smooth-shaded (render.meshes smooth = true).
Run: /usr/bin/python3 scripts/make_vase_obj.py > assets/meshes/vase.obj"""

import math
import sys

SLICES = 48
# (radius, height) from the base's rim up the outside, over the lip and down into the neck: a
# profile in metres for a vase 0.42 m tall.
PROFILE = [(0.07, 0.0), (0.10, 0.03), (0.14, 0.10), (0.15, 0.16), (0.13, 0.24), (0.08, 0.32),
           (0.06, 0.37), (0.07, 0.41), (0.085, 0.42), (0.075, 0.42), (0.055, 0.38),
           (0.05, 0.33)]


def main(out):
    out.write("# ClothLab vase: a surface of revolution (scripts/make_vase_obj.py)\n")
    for r, y in PROFILE:
        for s in range(SLICES):
            a = 2.0 * math.pi * s / SLICES
            out.write(f"v {r * math.cos(a):.5f} {y:.5f} {-r * math.sin(a):.5f}\n")
    # Centres closing the base (index n + 1) and the neck's bottom (n + 2).
    n = len(PROFILE) * SLICES
    out.write("v 0 0 0\n")
    out.write(f"v 0 {PROFILE[-1][1]:.5f} 0\n")
    def idx(ring, s):
        return ring * SLICES + s % SLICES + 1
    for ring in range(len(PROFILE) - 1):
        for s in range(SLICES):
            # Counter-clockwise seen from outside (the angle grows anticlockwise seen from +y).
            out.write(f"f {idx(ring, s)} {idx(ring, s + 1)} {idx(ring + 1, s + 1)} "
                      f"{idx(ring + 1, s)}\n")
    for s in range(SLICES):
        out.write(f"f {n + 1} {idx(0, s + 1)} {idx(0, s)}\n")  # base, facing down
        last = len(PROFILE) - 1
        out.write(f"f {n + 2} {idx(last, s)} {idx(last, s + 1)}\n")  # inside bottom, facing up


if __name__ == "__main__":
    main(sys.stdout)
