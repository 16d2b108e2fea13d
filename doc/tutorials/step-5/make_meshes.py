#!/usr/bin/env python3
"""The meshes of step-5, written as UCD (.inp) files, the way a user scripts a mesh of their own.

The fluid: the channel [0, 1.5] x [0, 0.5] m on a uniform grid of h = 0.025 m, less the cells the
flap [0.4, 0.45] x [0, 0.25] m occupies. The solid: the flap itself on its own, finer grid. Every
boundary face is written as a `line` cell whose material id is its boundary id (deal.II's
GridIn::read_ucd reads it so; a face left out would get id 0). Cells are listed with their
vertices counterclockwise.

  fluid (channel.inp): 0 inlet (x = 0), 1 outlet (x = 1.5), 2 walls (y = 0 and y = 0.5),
                       3 flap (the faces the flap touches)
  solid (flap.inp):    0 clamped (y = 0), 1 front (x = 0.4), 2 tip (y = 0.25), 3 back (x = 0.45)

usage: python3 make_meshes.py   (writes channel.inp and flap.inp next to this script)
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def write_ucd(name, vertices, quads, lines):
    """vertices [(x, y)], quads [(v0, v1, v2, v3)] counterclockwise, lines [(id, v0, v1)]."""
    with open(os.path.join(HERE, name), "w") as f:
        f.write("# %s: written by make_meshes.py\n" % name)
        f.write("%d %d 0 0 0\n" % (len(vertices), len(quads) + len(lines)))
        for i, (x, y) in enumerate(vertices):
            f.write("%d %.12g %.12g 0\n" % (i + 1, x, y))
        k = 1
        for q in quads:
            f.write("%d 0 quad %d %d %d %d\n" % (k, *[v + 1 for v in q]))
            k += 1
        for (b, v0, v1) in lines:
            f.write("%d %d line %d %d\n" % (k, b, v0 + 1, v1 + 1))
            k += 1


def grid(x0, y0, nx, ny, hx, hy, inside, boundary_id):
    """The cells (i, j) of an nx x ny grid for which inside(i, j) holds, and their boundary
    faces, each with boundary_id(i, j, side) (side: 'W', 'E', 'S', 'N')."""
    index = {}
    vertices = []

    def vertex(i, j):
        if (i, j) not in index:
            index[(i, j)] = len(vertices)
            vertices.append((x0 + i * hx, y0 + j * hy))
        return index[(i, j)]

    quads, lines = [], []
    for j in range(ny):
        for i in range(nx):
            if not inside(i, j):
                continue
            quads.append((vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)))
            for side, (di, dj), (a, b) in [("W", (-1, 0), ((i, j + 1), (i, j))),
                                           ("E", (1, 0), ((i + 1, j), (i + 1, j + 1))),
                                           ("S", (0, -1), ((i, j), (i + 1, j))),
                                           ("N", (0, 1), ((i + 1, j + 1), (i, j + 1)))]:
                ni, nj = i + di, j + dj
                if not (0 <= ni < nx and 0 <= nj < ny and inside(ni, nj)):
                    lines.append((boundary_id(i, j, side), vertex(*a), vertex(*b)))
    return vertices, quads, lines


def main():
    h = 0.025
    nx, ny = 60, 20                    # the channel 1.5 x 0.5 m
    flap_i, flap_j = (16, 18), (0, 10)  # the flap's cells: x in [0.4, 0.45], y in [0, 0.25]

    def in_flap(i, j):
        return flap_i[0] <= i < flap_i[1] and flap_j[0] <= j < flap_j[1]

    def fluid_id(i, j, side):
        if side == "W" and i == 0:
            return 0
        if side == "E" and i == nx - 1:
            return 1
        if (side == "S" and j == 0) or (side == "N" and j == ny - 1):
            return 2
        return 3  # a face of the flap

    write_ucd("channel.inp", *grid(0, 0, nx, ny, h, h, lambda i, j: not in_flap(i, j), fluid_id))

    sx, sy = 4, 20  # the flap 0.05 x 0.25 m
    ids = {"S": 0, "W": 1, "N": 2, "E": 3}
    write_ucd("flap.inp", *grid(0.4, 0, sx, sy, 0.05 / sx, 0.25 / sy, lambda i, j: True,
                                lambda i, j, side: ids[side]))


if __name__ == "__main__":
    main()
