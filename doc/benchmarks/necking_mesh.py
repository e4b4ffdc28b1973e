#!/usr/bin/env python3
"""Hexahedral mesh of one eighth of the necking bar of benchmark B-13, in
Gmsh's MSH 2.2 format (deal.II 9.4's GridIn reads it; no gmsh needed).

The bar lies along x, centred at the origin: 0 <= x <= L/2 (the centre
plane x = 0 is the neck), y >= 0, z >= 0 (a quarter of the disc). Its
radius grows linearly from taper * R at x = 0 to R at the end x = L/2
(Simo's imperfection; the dissertation reduces the centre to 0.99 d).

The quarter disc is an O-grid of three blocks: an inner block of n x n
cells and two outer blocks of n x m cells between it and the circle. Along
x there are nx layers, graded towards the neck: x_i = L/2 (i/nx)^grading.

Boundary ids (physical tags of the quadrilateral faces): 1 the centre plane
x = 0, 2 the plane y = 0, 3 the plane z = 0 (the three symmetry planes),
4 the clamped end x = L/2; the lateral surface is left untagged (id 0).

The defaults are those of prm/necking.prm: Simo's bar (53.334 x 6.413 mm)
scaled by 5/14.

Usage: necking_mesh.py out.msh [--length 19.048] [--radius 2.2904]
       [--taper 0.99] [--n 2] [--m 2] [--nx 8] [--grading 1.0]
"""
import argparse
import math


def quarter_disc(n, m):
    """Nodes (y, z) of the unit quarter disc and its quadrilaterals
    (counter-clockwise in the y-z plane)."""
    a = 0.5   # the inner block's corners on the axes: (a, 0), (0, a)
    b = 0.42  # and its corner on the diagonal: (b, b)
    nodes = {}
    coords = []

    def node(p):
        key = (round(p[0], 12), round(p[1], 12))
        if key not in nodes:
            nodes[key] = len(coords)
            coords.append(p)
        return nodes[key]

    def inner(u, v):  # bilinear map of the inner block
        c = [(0., 0.), (a, 0.), (b, b), (0., a)]
        w = [(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v]
        return (sum(wi * ci[0] for wi, ci in zip(w, c)),
                sum(wi * ci[1] for wi, ci in zip(w, c)))

    quads = []
    ids = [[node(inner(i / n, j / n)) for j in range(n + 1)]
           for i in range(n + 1)]
    for i in range(n):
        for j in range(n):
            quads.append((ids[i][j], ids[i + 1][j], ids[i + 1][j + 1],
                          ids[i][j + 1]))
    # lower outer block: between the inner edge u = 1 and the arc 0..45 deg
    low = []
    for k in range(m + 1):
        row = []
        for j in range(n + 1):
            p = inner(1., j / n)
            t = math.pi / 4 * j / n
            q = (math.cos(t), math.sin(t))
            s = k / m
            row.append(node(((1 - s) * p[0] + s * q[0],
                             (1 - s) * p[1] + s * q[1])))
        low.append(row)
    for k in range(m):
        for j in range(n):
            quads.append((low[k][j], low[k + 1][j], low[k + 1][j + 1],
                          low[k][j + 1]))
    # upper outer block: between the inner edge v = 1 and the arc 90..45 deg
    up = []
    for k in range(m + 1):
        row = []
        for i in range(n + 1):
            p = inner(i / n, 1.)
            t = math.pi / 2 - math.pi / 4 * i / n
            q = (math.cos(t), math.sin(t))
            s = k / m
            row.append(node(((1 - s) * p[0] + s * q[0],
                             (1 - s) * p[1] + s * q[1])))
        up.append(row)
    for k in range(m):
        for i in range(n):
            quads.append((up[k][i], up[k][i + 1], up[k + 1][i + 1],
                          up[k + 1][i]))
    return coords, quads


def signed_volume(p):
    """Six times the signed volume of the tetrahedron p[0], p[1], p[3],
    p[4] of a hexahedron (positive for a right-handed cell)."""
    a = [p[1][c] - p[0][c] for c in range(3)]
    b = [p[3][c] - p[0][c] for c in range(3)]
    c = [p[4][i] - p[0][i] for i in range(3)]
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) -
            a[1] * (b[0] * c[2] - b[2] * c[0]) +
            a[2] * (b[0] * c[1] - b[1] * c[0]))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--length", type=float, default=19.048)
    ap.add_argument("--radius", type=float, default=2.2904)
    ap.add_argument("--taper", type=float, default=0.99)
    ap.add_argument("--n", type=int, default=2)
    ap.add_argument("--m", type=int, default=2)
    ap.add_argument("--nx", type=int, default=8)
    ap.add_argument("--grading", type=float, default=1.0)
    o = ap.parse_args()

    disc, quads = quarter_disc(o.n, o.m)
    nd = len(disc)
    half = o.length / 2
    xs = [half * (i / o.nx) ** o.grading for i in range(o.nx + 1)]
    nodes = []
    for x in xs:
        r = o.radius * (o.taper + (1 - o.taper) * x / half)
        for (y, z) in disc:
            nodes.append((x, r * y, r * z))

    hexes = []
    for k in range(o.nx):
        for q in quads:
            h = [k * nd + v for v in q] + [(k + 1) * nd + v for v in q]
            if signed_volume([nodes[v] for v in h]) < 0:
                h = [h[0], h[3], h[2], h[1], h[4], h[7], h[6], h[5]]
            hexes.append(h)

    # boundary faces: the planes by their coordinates, the two ends by layer
    faces = []
    tol = 1e-9 * o.radius
    for q in quads:
        faces.append((1, [v for v in q]))
        faces.append((4, [o.nx * nd + v for v in q]))
    for k in range(o.nx):
        for q in quads:
            for e in range(4):
                a, b = q[e], q[(e + 1) % 4]
                for tag, c in ((2, 1), (3, 2)):
                    if abs(disc[a][c - 1]) < tol and abs(disc[b][c - 1]) < tol:
                        faces.append((tag, [k * nd + a, k * nd + b,
                                            (k + 1) * nd + b,
                                            (k + 1) * nd + a]))

    with open(o.out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write("$Nodes\n%d\n" % len(nodes))
        for i, p in enumerate(nodes):
            f.write("%d %.12g %.12g %.12g\n" % (i + 1, p[0], p[1], p[2]))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(faces) + len(hexes)))
        e = 1
        for tag, v in faces:
            f.write("%d 3 2 %d %d %s\n" % (e, tag, tag,
                                           " ".join(str(i + 1) for i in v)))
            e += 1
        for h in hexes:
            f.write("%d 5 2 1 1 %s\n" % (e, " ".join(str(i + 1) for i in h)))
            e += 1
        f.write("$EndElements\n")
    print("%s: %d nodes, %d hexahedra, %d boundary faces" %
          (o.out, len(nodes), len(hexes), len(faces)))


if __name__ == "__main__":
    main()
