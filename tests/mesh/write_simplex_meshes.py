#!/usr/bin/env python3
"""Write the small Gmsh (MSH 2.2 ASCII) simplex meshes of the tests.

Gmsh is not needed: a distorted quadrilateral (hexahedral) grid is split
into triangles (6 tetrahedra per cube, Kuhn's subdivision, which is
conforming across cubes), and the boundary lines (triangles) get the
physical tags of GridGenerator's colorized hyper_rectangle: x- 0, x+ 1,
y- 2, y+ 3, z- 4, z+ 5. Cells get physical tag 0 (material id 0).
Run it in tests/mesh/ to rewrite the files; the seed fixes them.

  distorted_triangles.msh   [-1,1]^2, 12 x 12 squares, 288 triangles,
                            interior vertices moved by up to 0.3 h
  distorted_tetrahedra.msh  [-1,1]^3, 4 x 4 x 4 cubes, 384 tetrahedra,
                            interior vertices moved by up to 0.2 h
  split_triangles.msh       [-1,1]^2, 6 x 6 squares, 72 triangles in two
                            blocks whose 7 vertices at x = 0 are duplicated
  second_order_triangles.msh  two 6-node triangles (refused)
  mixed_triangles_quads.msh   a triangle beside a quadrilateral (refused)
  flat_triangle.msh           a triangle whose vertices lie on a line
  inverted_triangle.msh       distorted_triangles.msh with a boundary triangle
                              numbered clockwise
"""
import itertools
import random


def write(name, nodes, elements):
    """nodes: list of (x, y, z); elements: list of (type, tag, [nodes])."""
    with open(name, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n")
        f.write(f"{len(nodes)}\n")
        for i, p in enumerate(nodes):
            f.write(f"{i + 1} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
        f.write("$EndNodes\n$Elements\n")
        f.write(f"{len(elements)}\n")
        for i, (kind, tag, vs) in enumerate(elements):
            f.write(f"{i + 1} {kind} 2 {tag} {tag} " +
                    " ".join(str(v + 1) for v in vs) + "\n")
        f.write("$EndElements\n")


def grid(n, dim, distortion, seed):
    """The vertices of an n^dim grid of [-1,1]^dim, interior ones moved."""
    rng = random.Random(seed)
    h = 2.0 / n
    nodes, index = [], {}
    for ijk in itertools.product(range(n + 1), repeat=dim):
        ijk = tuple(reversed(ijk))  # x fastest
        p = [-1 + h * c for c in ijk]
        if all(0 < c < n for c in ijk):
            p = [x + distortion * h * rng.uniform(-1, 1) for x in p]
        index[ijk] = len(nodes)
        nodes.append(p + [0.0] * (3 - dim))
    return nodes, index


def signed_measure(nodes, vs):
    if len(vs) == 3:
        (ax, ay, _), (bx, by, _), (cx, cy, _) = (nodes[v] for v in vs)
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    a, b, c, d = (nodes[v] for v in vs)
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] *
            (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]))


def oriented(nodes, vs):
    vs = list(vs)
    if signed_measure(nodes, vs) < 0:
        vs[0], vs[1] = vs[1], vs[0]
    return vs


def boundary_tag(points, dim, n=None):
    """The colorized id of a boundary face given by its grid indices."""
    n = n_of[dim] if n is None else n
    for d in range(dim):
        values = {p[d] for p in points}
        if len(values) == 1:
            v = values.pop()
            if v == 0:
                return 2 * d
            if v == n:
                return 2 * d + 1
    return None


n_of = {2: 12, 3: 4}


def triangles():
    n = n_of[2]
    nodes, index = grid(n, 2, 0.3, 49)
    elements = []
    for i in range(n):
        # boundary lines
        for a, b in (((i, 0), (i + 1, 0)), ((i, n), (i + 1, n)),
                     ((0, i), (0, i + 1)), ((n, i), (n, i + 1))):
            elements.append((1, boundary_tag([a, b], 2), [index[a], index[b]]))
    for i, j in itertools.product(range(n), repeat=2):
        v00, v10 = index[(i, j)], index[(i + 1, j)]
        v01, v11 = index[(i, j + 1)], index[(i + 1, j + 1)]
        # alternate the diagonal
        if (i + j) % 2 == 0:
            tris = [(v00, v10, v11), (v00, v11, v01)]
        else:
            tris = [(v00, v10, v01), (v10, v11, v01)]
        for t in tris:
            elements.append((2, 0, oriented(nodes, t)))
    write("distorted_triangles.msh", nodes, elements)
    # the same with one triangle at the bottom edge numbered clockwise
    first = next(i for i, e in enumerate(elements) if e[0] == 2)
    kind, tag, vs = elements[first + 1]
    elements[first + 1] = (kind, tag, [vs[1], vs[0], vs[2]])
    write("inverted_triangle.msh", nodes, elements)


def split_triangles():
    """A regular 6 x 6 triangle mesh in two blocks, x < 0 and x > 0, whose
    vertices at x = 0 are duplicated (blocks not merged by the mesher)."""
    n = 6
    nodes, index = grid(n, 2, 0.0, 49)
    copy = {}
    for j in range(n + 1):
        copy[(n // 2, j)] = len(nodes)
        nodes.append(list(nodes[index[(n // 2, j)]]))

    def vertex(i, j, right):
        if right and i == n // 2:
            return copy[(i, j)]
        return index[(i, j)]

    elements = []
    for i in range(n):
        for a, b in (((i, 0), (i + 1, 0)), ((i, n), (i + 1, n))):
            right = i >= n // 2
            elements.append((1, boundary_tag([a, b], 2, n),
                             [vertex(*a, right), vertex(*b, right)]))
        for a, b in (((0, i), (0, i + 1)), ((n, i), (n, i + 1))):
            elements.append((1, boundary_tag([a, b], 2, n),
                             [index[a], index[b]]))
    for i, j in itertools.product(range(n), repeat=2):
        right = i >= n // 2
        v00, v10 = vertex(i, j, right), vertex(i + 1, j, right)
        v01, v11 = vertex(i, j + 1, right), vertex(i + 1, j + 1, right)
        for t in [(v00, v10, v11), (v00, v11, v01)]:
            elements.append((2, 0, oriented(nodes, t)))
    write("split_triangles.msh", nodes, elements)


def tetrahedra():
    n = n_of[3]
    nodes, index = grid(n, 3, 0.2, 49)
    elements = []
    cells = []
    for ijk in itertools.product(range(n), repeat=3):
        for perm in itertools.permutations(range(3)):
            path = [tuple(ijk)]
            p = list(ijk)
            for d in perm:
                p[d] += 1
                path.append(tuple(p))
            cells.append(path)
    # boundary triangles: tetrahedron faces on the boundary of the cube
    for path in cells:
        for skip in range(4):
            face = [path[k] for k in range(4) if k != skip]
            tag = boundary_tag(face, 3)
            if tag is not None:
                elements.append((2, tag, [index[p] for p in face]))
    for path in cells:
        elements.append((4, 0, oriented(nodes, [index[p] for p in path])))
    write("distorted_tetrahedra.msh", nodes, elements)


def bad_meshes():
    # two 6-node triangles of the unit square (Gmsh type 9)
    nodes = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0, 0),
             (1, 0.5, 0), (0.5, 0.5, 0), (0.5, 1, 0), (0, 0.5, 0)]
    write("second_order_triangles.msh", nodes,
          [(9, 0, [0, 1, 2, 4, 5, 6]), (9, 0, [0, 2, 3, 6, 7, 8])])
    # a triangle beside a quadrilateral
    nodes = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0.5, 0)]
    write("mixed_triangles_quads.msh", nodes,
          [(3, 0, [0, 1, 2, 3]), (2, 0, [1, 4, 2])])
    # the second triangle's vertices lie on a line
    nodes = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (2, -1, 0)]
    write("flat_triangle.msh", nodes,
          [(2, 0, [0, 1, 2]), (2, 0, [1, 3, 2])])


if __name__ == "__main__":
    triangles()
    split_triangles()
    tetrahedra()
    bad_meshes()
