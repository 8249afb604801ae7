#!/usr/bin/python3
"""Checks that a figure holds its coloured marks (bars, markers), not only axes and text.

    check_colour.py FILE MIN_FRACTION

For figures whose real content compresses as well as an empty frame with its labels: the
largestep notebook's winners figure is a few flat bars, 28.8-33.9 kB as a PNG, and the same
frame with its title and labels but no bars is 28.1 kB, so a size check cannot tell them apart.
Counts the pixels whose channels spread by more than 60 of 255 (black, grey and white spread by
none): the bars cover about 15 % of the winners figure, the empty frame none.
"""
import sys

from PIL import Image


def coloured_fraction(path):
    image = Image.open(path).convert("RGB")
    coloured = sum(1 for r, g, b in image.getdata() if max(r, g, b) - min(r, g, b) > 60)
    return coloured / (image.size[0] * image.size[1])


def main():
    path, wanted = sys.argv[1], float(sys.argv[2])
    try:
        fraction = coloured_fraction(path)
    except OSError as error:
        print(f"{path}: {error}")
        return 1
    if fraction < wanted:
        print(f"{path}: {fraction:.2%} of its pixels coloured: no marks drawn (expected >= {wanted:.0%})")
        return 1
    print(f"ok: {path}: {fraction:.2%} of its pixels coloured")
    return 0


if __name__ == "__main__":
    sys.exit(main())
