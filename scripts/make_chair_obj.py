#!/usr/bin/python3
"""Writes assets/meshes/chair.obj: a simple chair made of boxes (seat, backrest, four legs), the
project's own mesh for the mesh-collider scene (nothing is downloaded). The boxes touch but do not
overlap, so the union stays a set of closed surfaces whose inside a ray-parity test finds.
Run: /usr/bin/python3 scripts/make_chair_obj.py > assets/meshes/chair.obj"""

import sys

# (centre, half extents) in metres; the seat's top is 0.46 m above the floor.
BOXES = [
    ((0.0, 0.44, 0.0), (0.22, 0.02, 0.22)),       # seat
    ((0.0, 0.71, -0.20), (0.22, 0.25, 0.02)),      # backrest, on the seat's back edge
    ((-0.19, 0.21, -0.19), (0.025, 0.21, 0.025)),  # legs, up to the seat's underside
    ((0.19, 0.21, -0.19), (0.025, 0.21, 0.025)),
    ((-0.19, 0.21, 0.19), (0.025, 0.21, 0.025)),
    ((0.19, 0.21, 0.19), (0.025, 0.21, 0.025)),
]

# Quads of a box's corners (bit 0: +x, bit 1: +y, bit 2: +z), wound outwards, 1-based.
FACES = [(1, 3, 4, 2), (5, 6, 8, 7), (1, 2, 6, 5), (3, 7, 8, 4), (1, 5, 7, 3), (2, 4, 8, 6)]


def main(out):
    out.write("# ClothLab chair: seat, backrest and four legs (scripts/make_chair_obj.py)\n")
    for b, ((cx, cy, cz), (hx, hy, hz)) in enumerate(BOXES):
        out.write(f"o box{b}\n")
        for k in range(8):
            x = cx + (hx if k & 1 else -hx)
            y = cy + (hy if k & 2 else -hy)
            z = cz + (hz if k & 4 else -hz)
            out.write(f"v {x:.4f} {y:.4f} {z:.4f}\n")
        base = 8 * b
        for f in FACES:
            out.write("f " + " ".join(str(base + i) for i in f) + "\n")


if __name__ == "__main__":
    main(sys.stdout)
