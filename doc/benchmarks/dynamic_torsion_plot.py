#!/usr/bin/env python3
"""B-14 (Fig. 7.26): the equivalent plastic strain of the twisted prism,
one panel per run, read from pg's VTU files (deal.II's zlib-compressed
binary XML; no ParaView or VTK needed). Each panel shows the points of the
run (the particles, or the cell centres of finite element cells) in their
deformed place, seen from the side (x + u_x against z + u_z), coloured by
the equivalent plastic strain on the scale of Fig. 7.26 (0 to the largest
value of all panels).

Usage (from the repository root):
  /usr/bin/python3 doc/benchmarks/dynamic_torsion_plot.py OUT.png TITLE:FILE.vtu [TITLE:FILE.vtu ...]
FILE.vtu is a piece (solution_NNNN.0.vtu or particles_NNNN.0.vtu) of a run
with 'Output/VTU = true' (dynamic_torsion.sh with KEEP=1).
"""
import base64
import re
import struct
import sys
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

FIELD = "equivalent_plastic_strain"
TYPES = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B", "Int64": "q"}


def decode(text, kind):
    """the values of one binary DataArray (vtkZLibDataCompressor, UInt32 header)"""
    text = text.strip()
    if not text:
        return []
    first = base64.b64decode(text[:8])
    blocks = struct.unpack("<I", first[:4])[0]
    header_bytes = 4 * (3 + blocks)
    header_chars = 4 * ((header_bytes + 2) // 3)
    header = struct.unpack("<%dI" % (3 + blocks), base64.b64decode(text[:header_chars])[:header_bytes])
    data = base64.b64decode(text[header_chars:])
    raw = b""
    offset = 0
    for size in header[3:]:
        raw += zlib.decompress(data[offset : offset + size])
        offset += size
    code = TYPES[kind]
    return list(struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code), code), raw))


def read_vtu(path):
    """points (list of 3-tuples), connectivity, offsets, point and cell data"""
    text = open(path).read()
    arrays = {}
    for section in ("Points", "Cells", "PointData", "CellData"):
        match = re.search(r"<%s[^>]*>(.*?)</%s>" % (section, section), text, re.S)
        if not match:
            continue
        for head, body in re.findall(r"<DataArray([^>]*)>(.*?)</DataArray>", match.group(1), re.S):
            kind = re.search(r'type="(\w+)"', head).group(1)
            name = re.search(r'Name="([^"]*)"', head)
            components = re.search(r'NumberOfComponents="(\d+)"', head)
            values = decode(body, kind)
            n = int(components.group(1)) if components else 1
            if n > 1:
                values = [tuple(values[i : i + n]) for i in range(0, len(values), n)]
            arrays[(section, name.group(1) if name else "points")] = values
    return arrays


def plastic_points(path):
    """(x + u_x, z + u_z, equivalent plastic strain) of the points of a piece"""
    a = read_vtu(path)
    points = a[("Points", "points")]
    u = a.get(("PointData", "displacement"), [(0, 0, 0)] * len(points))
    moved = [tuple(p[d] + w[d] for d in range(3)) for p, w in zip(points, u)]
    if ("PointData", FIELD) in a:
        return [(m[0], m[2], e) for m, e in zip(moved, a[("PointData", FIELD)])]
    # cell data: at the cell centres
    cells = a[("Cells", "connectivity")]
    offsets = a[("Cells", "offsets")]
    result = []
    start = 0
    for end, e in zip(offsets, a[("CellData", FIELD)]):
        corners = [moved[i] for i in cells[start:end]]
        start = end
        result.append((sum(c[0] for c in corners) / len(corners), sum(c[2] for c in corners) / len(corners), e))
    return result


def main():
    out = sys.argv[1]
    runs = [arg.split(":", 1) for arg in sys.argv[2:]]
    data = [(title, plastic_points(path)) for title, path in runs]
    top = max(max(e for _, _, e in p) for _, p in data) or 1.0
    fig, axes = plt.subplots(1, len(data), figsize=(2.8 * len(data) + 1.2, 6.0), squeeze=False)
    for ax, (title, p) in zip(axes[0], data):
        p.sort(key=lambda q: q[2])
        scatter = ax.scatter([q[0] for q in p], [q[1] for q in p], c=[q[2] for q in p], s=14, cmap="jet", vmin=0.0, vmax=top)
        ax.set_title("%s\nmax %.2f" % (title, max(q[2] for q in p)), fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlim(-0.4, 1.4)
        ax.set_xlabel("x + u_x (mm)")
    axes[0][0].set_ylabel("z + u_z (mm)")
    fig.colorbar(scatter, ax=axes[0].tolist(), label="equivalent plastic strain")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
