#!/usr/bin/env python3
"""Write the small Exodus II meshes of tests/exodus as netCDF CDL text and
convert them with ncgen (Debian: netcdf-bin):

    python3 make_test_meshes.py && for f in *.cdl; do ncgen -o ${f%.cdl}.g $f; done

bar_hex.g: the bar [0,3] x [0,1] x [0,1] of 3 x 2 x 2 HEX8 elements in two
element blocks (ids 1: x < 1, 2: x > 1) whose nodes at x = 1 are written
twice (Cubit's unmerged blocks); side set 7 = the face x = 3 (side 2 of the
elements there); node sets 'left' (x = 0, named) and id 5 (unnamed, the
edge x = 0, y = 0), and id 6 (unnamed, the corner (0, 0, 0)). Interior
nodes are moved in y and z, so that the numbering is checked by volumes.

spheres.g: Peridigm's particle format, 8 SPHERE elements of one node each
(pg refuses it: a particle cloud has no cells).

square_tri.g: the square [0,2] x [0,1] (num_dim = 2) of 4 x 2 cells, each
cut into two TRI3; one block (id 3); side set 4 = the edge x = 2; node set
'left' (x = 0) and id 2 (the corner (0, 0)).
"""


def cdl(name, dim, coords, blocks, side_sets, node_sets):
    """blocks: [(id, type, [[nodes 1-based]])], side_sets: [(id, [(elem,
    side)])], node_sets: [(id, name, [nodes])]"""
    out = []
    w = out.append
    w("netcdf %s {" % name)
    w("dimensions:")
    w("\tlen_string = 33 ;\n\tlen_line = 81 ;\n\tfour = 4 ;")
    w("\ttime_step = UNLIMITED ;")
    w("\tnum_dim = %d ;" % dim)
    w("\tnum_nodes = %d ;" % len(coords))
    w("\tnum_elem = %d ;" % sum(len(b[2]) for b in blocks))
    w("\tnum_el_blk = %d ;" % len(blocks))
    if side_sets:
        w("\tnum_side_sets = %d ;" % len(side_sets))
    if node_sets:
        w("\tnum_node_sets = %d ;" % len(node_sets))
    for i, (sid, sides) in enumerate(side_sets):
        w("\tnum_side_ss%d = %d ;" % (i + 1, len(sides)))
    for i, (nid, nname, nodes) in enumerate(node_sets):
        w("\tnum_nod_ns%d = %d ;" % (i + 1, len(nodes)))
    for i, (bid, btype, elems) in enumerate(blocks):
        w("\tnum_el_in_blk%d = %d ;" % (i + 1, len(elems)))
        w("\tnum_nod_per_el%d = %d ;" % (i + 1, len(elems[0])))
    w("variables:")
    w("\tdouble time_whole(time_step) ;")
    w("\tint eb_prop1(num_el_blk) ;\n\t\teb_prop1:name = \"ID\" ;")
    if side_sets:
        w("\tint ss_prop1(num_side_sets) ;\n\t\tss_prop1:name = \"ID\" ;")
        for i in range(len(side_sets)):
            w("\tint elem_ss%d(num_side_ss%d) ;" % (i + 1, i + 1))
            w("\tint side_ss%d(num_side_ss%d) ;" % (i + 1, i + 1))
    if node_sets:
        w("\tint ns_prop1(num_node_sets) ;\n\t\tns_prop1:name = \"ID\" ;")
        w("\tchar ns_names(num_node_sets, len_string) ;")
        for i in range(len(node_sets)):
            w("\tint node_ns%d(num_nod_ns%d) ;" % (i + 1, i + 1))
    for i, (bid, btype, elems) in enumerate(blocks):
        w("\tint connect%d(num_el_in_blk%d, num_nod_per_el%d) ;" %
          (i + 1, i + 1, i + 1))
        w("\t\tconnect%d:elem_type = \"%s\" ;" % (i + 1, btype))
    for c in "xyz"[:dim]:
        w("\tdouble coord%s(num_nodes) ;" % c)
    w("\n// global attributes:\n\t\t:api_version = 4.98f ;")
    w("\t\t:version = 4.98f ;\n\t\t:floating_point_word_size = 8 ;")
    w("\t\t:file_size = 1 ;\n\t\t:title = \"pg test mesh %s\" ;" % name)
    w("data:")

    def lst(values):
        return ", ".join(str(v) for v in values)
    w(" eb_prop1 = %s ;" % lst(b[0] for b in blocks))
    if side_sets:
        w(" ss_prop1 = %s ;" % lst(s[0] for s in side_sets))
        for i, (sid, sides) in enumerate(side_sets):
            w(" elem_ss%d = %s ;" % (i + 1, lst(e for e, s in sides)))
            w(" side_ss%d = %s ;" % (i + 1, lst(s for e, s in sides)))
    if node_sets:
        w(" ns_prop1 = %s ;" % lst(n[0] for n in node_sets))
        w(" ns_names = %s ;" % ", ".join('"%s"' % n[1] for n in node_sets))
        for i, (nid, nname, nodes) in enumerate(node_sets):
            w(" node_ns%d = %s ;" % (i + 1, lst(nodes)))
    for i, (bid, btype, elems) in enumerate(blocks):
        w(" connect%d = %s ;" % (i + 1, lst(n for e in elems for n in e)))
    for d, c in enumerate("xyz"[:dim]):
        w(" coord%s = %s ;" % (c, lst(repr(p[d]) for p in coords)))
    w("}")
    return "\n".join(out) + "\n"


def bar_hex():
    nx, ny, nz = 3, 2, 2
    coords, index = [], {}

    def node(i, j, k, copy):
        key = (i, j, k, copy)
        if key not in index:
            y, z = j / ny, k / nz
            # move the interior nodes (j, k = 1) in y and z
            if 0 < j < ny and 0 < k < nz:
                y += 0.1 * (i % 2 - 0.5)
                z -= 0.05 * (i + 1)
            coords.append((float(i), y, z))
            index[key] = len(coords)
        return index[key]
    blocks = []
    element = 0
    side_set = []
    for block_id, irange in ((1, [0]), (2, [1, 2])):
        elems = []
        for i in irange:
            for k in range(nz):
                for j in range(ny):
                    # the block 2 copy of the nodes at x = 1
                    c = lambda ii: 1 if (block_id == 2 and ii == 1) else 0
                    n = [node(i, j, k, c(i)), node(i + 1, j, k, c(i + 1)),
                         node(i + 1, j + 1, k, c(i + 1)),
                         node(i, j + 1, k, c(i)),
                         node(i, j, k + 1, c(i)),
                         node(i + 1, j, k + 1, c(i + 1)),
                         node(i + 1, j + 1, k + 1, c(i + 1)),
                         node(i, j + 1, k + 1, c(i))]
                    elems.append(n)
                    element += 1
                    if i == nx - 1:
                        side_set.append((element, 2))  # nodes 2,3,7,6: x = 3
        blocks.append((block_id, "HEX8", elems))
    left = [index[(0, j, k, 0)] for k in range(nz + 1) for j in range(ny + 1)]
    edge = [index[(0, 0, k, 0)] for k in range(nz + 1)]
    corner = [index[(0, 0, 0, 0)]]
    return cdl("bar_hex", 3, coords, blocks, [(7, side_set)],
               [(1, "left", left), (5, "", edge), (6, "", corner)])


def square_tri():
    nx, ny = 4, 2
    coords = [(2.0 * i / nx, j / ny) for j in range(ny + 1)
              for i in range(nx + 1)]
    n = lambda i, j: j * (nx + 1) + i + 1
    elems, side_set = [], []
    for j in range(ny):
        for i in range(nx):
            elems.append([n(i, j), n(i + 1, j), n(i + 1, j + 1)])
            if i == nx - 1:
                side_set.append((len(elems), 2))  # nodes 2,3: x = 2
            elems.append([n(i, j), n(i + 1, j + 1), n(i, j + 1)])
    left = [n(0, j) for j in range(ny + 1)]
    return cdl("square_tri", 2, coords, [(3, "TRI3", elems)],
               [(4, side_set)], [(1, "left", left), (2, "", [n(0, 0)])])


def spheres():
    coords = [(float(i), float(j), float(k)) for k in range(2)
              for j in range(2) for i in range(2)]
    return cdl("spheres", 3, coords,
               [(1, "SPHERE", [[n + 1] for n in range(8)])], [], [])


if __name__ == "__main__":
    for name, text in (("bar_hex", bar_hex()), ("square_tri", square_tri()),
                       ("spheres", spheres())):
        with open(name + ".cdl", "w") as f:
            f.write(text)
