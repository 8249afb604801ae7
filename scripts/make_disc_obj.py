#!/usr/bin/python3
"""Writes assets/meshes/round_cloth.obj: a round cloth (a disc in the xz plane, facing +y) as a
triangle mesh with no grid in it: ring k of K has 6k vertices, so the triangles stay close to
equilateral from the centre out (the cloth of the mesh-cloth scene; nothing is downloaded).
Run: /usr/bin/python3 scripts/make_disc_obj.py [radius] [rings] > assets/meshes/round_cloth.obj"""

import math
import sys


def ring_start(k):
    """Index (0-based) of ring k's first vertex: the centre is 0, ring k has 6k vertices."""
    return 0 if k == 0 else 1 + 3 * k * (k - 1)


def main(out, radius, rings):
    out.write(f"# ClothLab round cloth, radius {radius} m, {rings} rings (scripts/make_disc_obj.py)\n")
    out.write("v 0 0 0\n")
    for k in range(1, rings + 1):
        r = radius * k / rings
        for s in range(6 * k):
            a = 2.0 * math.pi * s / (6 * k)
            out.write(f"v {r * math.cos(a):.6f} 0 {-r * math.sin(a):.6f}\n")
    # Between ring k - 1 and ring k: walk both rings by angle, always advancing the one whose next
    # vertex comes first, so every triangle joins the two rings (counter-clockwise seen from +y).
    for k in range(1, rings + 1):
        inner_n, outer_n = max(1, 6 * (k - 1)), 6 * k
        i = o = 0
        while i < (inner_n if k > 1 else 0) or o < outer_n:
            inner = ring_start(k - 1) + i % inner_n
            outer = ring_start(k) + o % outer_n
            next_inner_angle = (i + 1) / inner_n if k > 1 else 2.0
            next_outer_angle = (o + 1) / outer_n
            if k > 1 and next_inner_angle < next_outer_angle - 1e-12:
                nxt = ring_start(k - 1) + (i + 1) % inner_n
                out.write(f"f {inner + 1} {outer + 1} {nxt + 1}\n")
                i += 1
            else:
                nxt = ring_start(k) + (o + 1) % outer_n
                out.write(f"f {inner + 1} {outer + 1} {nxt + 1}\n")
                o += 1


if __name__ == "__main__":
    radius = float(sys.argv[1]) if len(sys.argv) > 1 else 0.8
    rings = int(sys.argv[2]) if len(sys.argv) > 2 else 16
    main(sys.stdout, radius, rings)
