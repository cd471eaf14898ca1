# SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkIceProperty::BubbleDensity, measured on ice-render's pictures of the cube in the sky (no
core fog, no air planes, no cracks): what the bubbles add against the same picture without them.

usage: TestIceBubbles.py ICE_RENDER WORK_DIR CASE   (Debian's /usr/bin/python3, for vtk)
  specks    the bubbles are many separate specks, small ones most, a few several times larger
  centre    they gather in the middle of the ice: the middle third of its extent on the screen
            holds at least three times the share of its outer sixth
  frontal   seen straight along a face's normal (down the bubbles' grid) they brighten nearly as
            many pixels as seen 12 degrees off it, not a sparse lattice of dots (the grid's walk
            once lost its way there)
  slanted   seen through the top face from 14 degrees above it, they show there at least a fifth
            as densely as through the front face: the light refracted at the top face runs down
            into the cloud (along the eye ray, it grazed above the cloud and the top face showed
            none: 0.07 % of its pixels against 25 % of the front face's)
"""
import os
import sys

from ice_render_tool import Checks, render as render_tool

ICE_RENDER, WORK, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
WIDTH, HEIGHT = 480, 360
SCENE = ("--model", "cube", "--env", "sky", "--static", "--size", "%dx%d" % (WIDTH, HEIGHT),
         "--preset", "clear", "--milky-core", "0.5", "--milkiness", "0", "--air", "0",
         "--cracks", "0", "--bubbles", "1")
FRONTAL = ("--camera-position", "0,0,6.5", "--focal-point", "0,0,0", "--view-up", "0,1,0")
# 6.5 units away too, 12 degrees off the face's normal, sideways and upwards.
TILTED = ("--camera-position", "1.35,0.9,6.29", "--focal-point", "0,0,0", "--view-up", "0,1,0")
# 6.5 units away, 14 degrees above the top face's plane.
SLANTED = ("--camera-position", "0,1.6,6.3", "--focal-point", "0,0,0", "--view-up", "0,1,0")
check = Checks()


def render(name, *args):
    pixels, error = render_tool(ICE_RENDER, WORK, name, *SCENE, *args)
    if error is not None:
        sys.exit("ice-render %s: %s" % (" ".join(args), error))
    return pixels


def bubble_pixels(name, *args):
    """The pixels the bubbles brighten by more than 12/255 (indices, row by row from the bottom)."""
    with_bubbles = render(name, *args)
    without = render(name + "-none", *args, "--bubbles", "0")
    return set(i for i, (p, q) in enumerate(zip(with_bubbles, without)) if sum(p) - sum(q) > 36)


def specks(pixels):
    """The sizes of the 4-connected groups of pixels."""
    sizes, left = [], set(pixels)
    while left:
        stack, size = [left.pop()], 0
        while stack:
            i = stack.pop()
            size += 1
            x, y = i % WIDTH, i // WIDTH
            for j, ok in ((i - 1, x > 0), (i + 1, x < WIDTH - 1), (i - WIDTH, y > 0),
                          (i + WIDTH, y < HEIGHT - 1)):
                if ok and j in left:
                    left.remove(j)
                    stack.append(j)
        sizes.append(size)
    return sorted(sizes)


def main():
    os.makedirs(WORK, exist_ok=True)
    if CASE == "specks":
        sizes = specks(bubble_pixels("side"))
        median = sizes[len(sizes) // 2] if sizes else 0
        large = sizes[int(0.99 * len(sizes))] if sizes else 0
        check("the bubbles are many specks, small ones most, a few larger",
              len(sizes) >= 300 and median <= 4 and large >= 3 * median,
              "%d specks, median %d pixels, 99th percentile %d" % (len(sizes), median, large))
    elif CASE == "centre":
        bubbles = bubble_pixels("side")
        ice = render("side-mask", "--debug-view", "front-depth")
        plain = render("side-plain", "--bubbles", "0")
        area = [i for i, (p, q) in enumerate(zip(ice, plain)) if p != q]
        xs, ys = [i % WIDTH for i in area], [i // WIDTH for i in area]
        x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)

        def where(i):
            u, v = (i % WIDTH - x0) / max(x1 - x0, 1), (i // WIDTH - y0) / max(y1 - y0, 1)
            edge = min(u, 1 - u, v, 1 - v)
            return "centre" if edge > 1 / 3 else "rim" if edge < 1 / 6 else "between"

        counts = {"centre": [0, 0], "rim": [0, 0], "between": [0, 0]}
        for i in area:
            counts[where(i)][0] += i in bubbles
            counts[where(i)][1] += 1
        share = {k: a / max(n, 1) for k, (a, n) in counts.items()}
        check("the bubbles gather in the middle of the ice",
              share["centre"] >= 0.1 and share["centre"] >= 3 * share["rim"],
              "%.1f %% of the middle's pixels, %.1f %% of the rim's" %
              (100 * share["centre"], 100 * share["rim"]))
    elif CASE == "frontal":
        tilted, front = len(bubble_pixels("tilted", *TILTED)), len(bubble_pixels("front", *FRONTAL))
        check("seen along a face's normal the bubbles are nearly as many as 12 degrees off it",
              tilted > 1000 and front >= 0.8 * tilted,
              "%d pixels brightened 12 degrees off the normal, %d along it" % (tilted, front))
    elif CASE == "slanted":
        bubbles = bubble_pixels("slanted", *SLANTED)
        ice = render("slanted-mask", *SLANTED, "--debug-view", "front-depth")
        plain = render("slanted-plain", *SLANTED, "--bubbles", "0")
        area = [i for i, (p, q) in enumerate(zip(ice, plain)) if p != q]
        y0, y1 = min(i // WIDTH for i in area), max(i // WIDTH for i in area)

        def density(low, high):
            """The share of bubble pixels in a band of the ice's rows (0: its bottom, 1: top)."""
            band = [i for i in area if low <= (i // WIDTH - y0) / max(y1 - y0, 1) < high]
            return sum(i in bubbles for i in band) / max(len(band), 1)

        top, front = density(0.9, 1.01), density(0.3, 0.7)
        check("through a face seen at a slant the bubbles show where the refracted light is",
              front >= 0.1 and top >= 0.2 * front,
              "%.2f %% of the top face's pixels, %.1f %% of the front face's" %
              (100 * top, 100 * front))
    else:
        sys.exit("unknown case " + CASE)
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
