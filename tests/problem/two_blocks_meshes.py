#!/usr/bin/env python3
"""Write the Gmsh 2.2 meshes of tests/problem/mesh_merge_01: the box
[0,2] x [0,1] (x [0,1] in 3-D) of 8 x 4 (4 x 2 x 2) cells as two blocks,
physical ids 1 (x < 1) and 2 (x > 1). The '_unmerged' files give each block
its own nodes, so the nodes on x = 1 appear twice, as in a Cubit/Exodus mesh
whose blocks were not merged (Peridigm's tensile_test.g has 252 such pairs).
Run from this directory: python3 two_blocks_meshes.py"""


def write(name, dim, merged, n=(4, 2, 2)):
    nx, ny = n[0], n[1]
    nz = n[2] if dim == 3 else 0
    half = nx // 2
    nodes, index = [], {}

    def node(block, i, j, k):
        # the nodes on x = 1 once per block unless merged
        key = (i, j, k) if merged or i != half else (block, i, j, k)
        if key not in index:
            nodes.append((2.0 * i / nx, 1.0 * j / ny, 1.0 * k / nz if nz else 0.0))
            index[key] = len(nodes)
        return index[key]

    elements = []
    for k in range(max(nz, 1)):
        for j in range(ny):
            for i in range(nx):
                block = 1 if i < half else 2
                c = lambda di, dj, dk: node(block, i + di, j + dj, k + dk)
                if dim == 2:
                    elements.append((3, block, [c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0)]))
                else:
                    elements.append((5, block, [c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0),
                                                c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)]))
    with open(name, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for m, p in enumerate(nodes, 1):
            f.write("%d %.17g %.17g %.17g\n" % (m, *p))
        f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for m, (t, block, v) in enumerate(elements, 1):
            f.write("%d %d 2 %d %d %s\n" % (m, t, block, block, " ".join(map(str, v))))
        f.write("$EndElements\n")


for dim in (2, 3):
    for merged in (True, False):
        write("two_blocks_%dd%s.msh" % (dim, "" if merged else "_unmerged"), dim, merged,
              (8, 4, 0) if dim == 2 else (4, 2, 2))
