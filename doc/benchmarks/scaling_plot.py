#!/usr/bin/env python3
"""Plots of doc/benchmarks/scaling.md from the rows scaling.sh printed.

Usage: python3 doc/benchmarks/scaling_plot.py TABLE.md OUTPUT_PREFIX
writes OUTPUT_PREFIX_time.png (seconds per Newton step and its ratio to FEM
against DoFs) and OUTPUT_PREFIX_memory.png (peak kB per DoF and Krylov
iterations per solve against DoFs), one line per (dimension, formulation,
horizon factor, ranks).
"""
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

table, prefix = sys.argv[1], sys.argv[2]
series = defaultdict(list)
for line in open(table):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) < 20 or not cells[5].isdigit():
        continue
    dim, formulation, factor, ranks = cells[0], cells[1], cells[2], cells[3]
    label = "%s %s%s, %s rank%s" % (dim, formulation,
                                    " %sh" % factor if factor else "",
                                    ranks, "s" if ranks != "1" else "")
    series[label].append({
        "dofs": int(cells[5]),
        "its": float(cells[11]),
        "step": float(cells[14]),
        "ratio": float(cells[15]) if cells[15] != "-" else None,
        "kB": float(cells[18]),
    })


def finish(axis, ylabel):
    """Label, grid and legend of one panel."""
    axis.set_xlabel("DoFs")
    axis.set_ylabel(ylabel)
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=7)


fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5))
for label, rows in sorted(series.items()):
    rows.sort(key=lambda r: r["dofs"])
    dofs = [r["dofs"] for r in rows]
    left.loglog(dofs, [r["step"] for r in rows], "o-", label=label)
    ratio = [(r["dofs"], r["ratio"]) for r in rows if r["ratio"] is not None]
    if ratio:
        right.semilogx(*zip(*ratio), "o-", label=label)
right.axhline(1.6, color="k", ls="--", lw=1, label="issue 14 target 1.6")
finish(left, "wall s per Newton step (assembly + solve)")
finish(right, "s per Newton step / FEM's at the same size")
fig.tight_layout()
fig.savefig(prefix + "_time.png", dpi=110)

fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5))
for label, rows in sorted(series.items()):
    dofs = [r["dofs"] for r in rows]
    left.semilogx(dofs, [r["kB"] for r in rows], "o-", label=label)
    right.semilogx(dofs, [r["its"] for r in rows], "o-", label=label)
finish(left, "peak memory, kB per DoF (all ranks)")
finish(right, "Krylov iterations per Newton solve")
fig.tight_layout()
fig.savefig(prefix + "_memory.png", dpi=110)
