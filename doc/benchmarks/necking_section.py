#!/usr/bin/env python3
"""The equivalent plastic strain of a B-13 necking run on the longitudinal
section z = 0, as a table for gnuplot (no ParaView, no numpy).

Reads a pg VTU file: particles_<step>.vtu (PG: one row per particle on
the plane z = 0) or solution_<step>.vtu (FEM: one row per cell next to
the plane, at its centre; the cell value). The deformed positions
x + u_x, y + u_y are mirrored across x = 0 and y = 0, so that the table
shows the whole section of the bar.

Usage: necking_section.py <output directory> > section.txt (the last
step's particles_*.0.vtu, or solution_*.0.vtu if it has no particles), or
necking_section.py file.vtu > section.txt
Columns: x (mm), y (mm), equivalent plastic strain.
"""
import base64
import re
import struct
import sys
import zlib


def decode(text, dtype, header64):
    """The values of a binary (zlib-compressed, base64) VTU DataArray."""
    text = "".join(text.split())
    hsize = 8 if header64 else 4
    fmt = "<Q" if header64 else "<I"
    # the header: number of blocks, block size, last block size, sizes
    head_len = 4 * ((3 * hsize + 2) // 3)
    first = base64.b64decode(text[:head_len])
    nblocks = struct.unpack(fmt, first[:hsize])[0]
    full_head = (3 + nblocks) * hsize
    head_len = 4 * ((full_head + 2) // 3)
    head = base64.b64decode(text[:head_len])
    sizes = [struct.unpack(fmt, head[(3 + i) * hsize:(4 + i) * hsize])[0]
             for i in range(nblocks)]
    raw = base64.b64decode(text[head_len:])
    data = b""
    pos = 0
    for s in sizes:
        data += zlib.decompress(raw[pos:pos + s])
        pos += s
    code = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
            "UInt8": "B", "UInt32": "I", "UInt64": "Q"}[dtype]
    n = len(data) // struct.calcsize(code)
    return struct.unpack("<%d%s" % (n, code), data)


def arrays(xml, section):
    """name -> (number of components, values) of the DataArrays in the XML
    element <section> (Points, PointData, CellData, Cells)."""
    m = re.search(r"<%s[^>]*>(.*?)</%s>" % (section, section), xml, re.S)
    out = {}
    if not m:
        return out
    header64 = 'header_type="UInt64"' in xml
    for a in re.finditer(r"<DataArray([^>]*)>(.*?)</DataArray>", m.group(1),
                         re.S):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', a.group(1)))
        name = attrs.get("Name", section)
        ncomp = int(attrs.get("NumberOfComponents", "1"))
        if attrs.get("format") == "binary":
            values = decode(a.group(2), attrs["type"], header64)
        else:
            values = [float(v) for v in a.group(2).split()]
        out[name] = (ncomp, values)
    return out


def main():
    import glob
    import os
    name = sys.argv[1]
    if os.path.isdir(name):
        files = sorted(glob.glob(os.path.join(name, "particles_*.0.vtu")))
        if not files or 'NumberOfPoints="0"' in open(files[-1]).read(2000):
            files = sorted(glob.glob(os.path.join(name, "solution_*.0.vtu")))
        if not files:
            return
        name = files[-1]
    xml = open(name).read()
    points = arrays(xml, "Points")
    if not points:
        return
    pts = list(points.values())[0][1]
    pdata = arrays(xml, "PointData")
    cdata = arrays(xml, "CellData")
    disp = None
    for name in pdata:
        if "displacement" in name and pdata[name][0] == 3:
            disp = pdata[name][1]
    npts = len(pts) // 3
    if disp is None:
        disp = [0.] * (3 * npts)
    x = [(pts[3 * i] + disp[3 * i], pts[3 * i + 1] + disp[3 * i + 1],
          pts[3 * i + 2]) for i in range(npts)]
    rows = []
    if "equivalent_plastic_strain" in pdata:  # particles: values per point
        ep = pdata["equivalent_plastic_strain"][1]
        zs = sorted(p[2] for p in x)
        tol = 1e-9 * max(1., zs[-1])
        for p, e in zip(x, ep):
            if abs(p[2]) < tol:
                rows.append((p[0], p[1], e))
    elif "equivalent_plastic_strain" in cdata:  # FE cells: cell centres
        ep = cdata["equivalent_plastic_strain"][1]
        cells = arrays(xml, "Cells")
        conn = cells["connectivity"][1]
        offsets = cells["offsets"][1]
        start = 0
        centres = []
        for c, end in enumerate(offsets):
            ids = conn[start:end]
            start = end
            centres.append([sum(x[i][d] for i in ids) / len(ids)
                            for d in range(3)] +
                           [min(x[i][2] for i in ids)])
        for c, e in zip(centres, ep):
            if abs(c[3]) < 1e-9:  # a cell with a face on z = 0
                rows.append((c[0], c[1], e))
    for (px, py, e) in rows:
        for sx in (1, -1):
            for sy in (1, -1):
                print("%.6g %.6g %.6g" % (sx * px, sy * py, e))


if __name__ == "__main__":
    main()
