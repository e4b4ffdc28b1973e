"""Read the deal.II VTU files that pg writes (particles_*.vtu and
solution_*.vtu: zlib-compressed base64 'binary' DataArrays, or ascii) into
numpy arrays, without VTK/ParaView: read_vtu(path) returns a dict with
'points' (n x 3), 'cells' (connectivity, m x nodes per cell or None),
'point_data' and 'cell_data' (name -> array)."""
import base64
import re
import struct
import zlib

import numpy as np

_TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32,
          "Int64": np.int64, "UInt8": np.uint8, "UInt32": np.uint32,
          "UInt64": np.uint64}


def _decode(text, dtype, compressed, header_type):
    text = "".join(text.split())
    if not compressed:
        raw = base64.b64decode(text)
        hsize = np.dtype(header_type).itemsize
        return np.frombuffer(raw[hsize:], dtype=dtype)
    h = np.dtype(header_type)
    first = base64.b64decode(text[:((3 * h.itemsize + 2) // 3) * 4 + 8])
    nblocks = int(np.frombuffer(first[:h.itemsize], dtype=h)[0])
    hbytes = (3 + nblocks) * h.itemsize
    hchars = ((hbytes + 2) // 3) * 4
    header = np.frombuffer(base64.b64decode(text[:hchars])[:hbytes], dtype=h)
    sizes = header[3:]
    body = base64.b64decode(text[hchars:])
    out, pos = [], 0
    for s in sizes:
        out.append(zlib.decompress(body[pos:pos + int(s)]))
        pos += int(s)
    return np.frombuffer(b"".join(out), dtype=dtype)


def read_vtu(path):
    xml = open(path).read()
    compressed = "vtkZLibDataCompressor" in xml
    hm = re.search(r'header_type="(\w+)"', xml)
    header_type = _TYPES[hm.group(1)] if hm else np.uint32
    arrays = []
    for m in re.finditer(r"<DataArray([^>]*)>(.*?)</DataArray>", xml, re.S):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        dtype = _TYPES[attrs["type"]]
        if attrs.get("format", "ascii") == "ascii":
            data = np.array(m.group(2).split(), dtype=dtype)
        else:
            data = _decode(m.group(2), dtype, compressed, header_type)
        ncomp = int(attrs.get("NumberOfComponents", 1))
        if ncomp > 1:
            data = data.reshape(-1, ncomp)
        arrays.append((m.start(), attrs.get("Name", ""), data))

    def section(tag):
        s = xml.find("<" + tag)
        if s < 0:
            return {}
        e = xml.find("</" + tag + ">", s)
        return {n: d for p, n, d in arrays if s < p < e}

    pts = section("Points")
    points = list(pts.values())[0].astype(float) if pts else None
    cells = section("Cells")
    conn = cells.get("connectivity")
    offsets = cells.get("offsets")
    if conn is not None and offsets is not None and len(offsets) > 0:
        nper = int(offsets[0])
        conn = conn.reshape(-1, nper)
    return {"points": points, "cells": conn,
            "point_data": section("PointData"),
            "cell_data": section("CellData")}
