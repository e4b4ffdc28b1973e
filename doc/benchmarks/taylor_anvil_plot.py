"""Pictures of doc/benchmarks/taylor_anvil.md (B-15 Fig. 7.29, B-16 Fig.
7.31): the equivalent plastic strain on the deformed section y = 0 of the
quarter rod, mirrored to the full section, from the last solution VTU of
each run (cell data 'equivalent_plastic_strain': the mean over a meshfree
cell's particles, or over an FE cell's Gauss points).
Usage: taylor_anvil_plot.py <directory of <tag>_solution_<when>.vtu> <figure directory> [b16]"""
import glob
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from taylor_anvil_vtu import read_vtu

# VTK hexahedron faces (local vertex numbers)
FACES = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5),
         (2, 3, 7, 6), (3, 0, 4, 7)]


def section(path, field="equivalent_plastic_strain"):
    """Polygons (x, z deformed) of the cell faces on y = 0 and their
    cell values."""
    d = read_vtu(path)
    X = d["points"]
    x = X + d["point_data"]["displacement"]
    # deal.II writes cell data as point data of each cell's own vertices
    values = (d["cell_data"][field] if field in d["cell_data"] else
              d["point_data"][field][d["cells"][:, 0]])
    polys, vals = [], []
    for c, cell in enumerate(d["cells"]):
        for f in FACES:
            ids = [cell[i] for i in f]
            if np.all(np.abs(X[ids, 1]) < 1e-9):
                polys.append(x[ids][:, [0, 2]])
                vals.append(values[c])
    return polys, np.array(vals)


def draw(ax, path, vmax, title):
    polys, vals = section(path)
    mirrored = [p * np.array([-1.0, 1.0]) for p in polys]
    pc = PolyCollection(polys + mirrored, array=np.concatenate([vals, vals]),
                        cmap="jet", edgecolors="k", linewidths=0.1)
    pc.set_clim(0, vmax)
    ax.add_collection(pc)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(title, fontsize=8)
    ax.set_xlabel("x (mm)", fontsize=7)
    ax.tick_params(labelsize=6)
    return pc, vals.max() if len(vals) else 0.0


def name_of(tag):
    f, n = tag.rsplit("_N", 1)
    f = f.replace("b16_", "").replace("_p_", "+").replace("_", " ")
    return "%s, N = %s" % (f, n)


def main():
    vtu_dir, fig_dir = sys.argv[1:3]
    b16 = len(sys.argv) > 3
    if b16:
        # every B-16 run: the section at 3 us, its impact region magnified
        # (the gap between rod and wall: the cavity), and the last output
        files = sorted(glob.glob(os.path.join(vtu_dir, "b16_*_solution_0003.vtu")))
        if not files:
            return
        fig, axs = plt.subplots(len(files), 3, figsize=(13, 3.6 * len(files)),
                                squeeze=False)
        pc = None
        for row, f3 in zip(axs, files):
            tag = os.path.basename(f3)[:-len("_solution_0003.vtu")]
            pc, m = draw(row[0], f3, 3.0, "")
            row[0].set_title("B-16 %s, t = 3 us (max cell value %.2f)" % (name_of(tag), m), fontsize=8)
            row[0].set_ylabel("z (mm)", fontsize=7)
            draw(row[1], f3, 3.0, "")
            row[1].set_aspect("auto")
            row[1].set_xlim(-6.5, 6.5)
            row[1].set_ylim(-0.05, 0.6)
            row[1].axhline(0, color="k", lw=1.5)
            row[1].set_title("impact end at 3 us, z magnified (black: the wall)", fontsize=8)
            last = os.path.join(vtu_dir, tag + "_solution_final.vtu")
            if os.path.exists(last):
                pc, m = draw(row[2], last, 3.0, "")
                row[2].set_aspect("auto")
                row[2].set_title("last output before the end or the failure\n(max cell value %.2f; z and x not to scale)" % m, fontsize=8)
        fig.colorbar(pc, ax=list(axs.ravel()), label="equivalent plastic strain (cell mean)")
        out = os.path.join(fig_dir, "taylor_anvil_b16.png")
        fig.savefig(out, dpi=120, bbox_inches="tight")
        print("wrote", out)
        return
    files = sorted(glob.glob(os.path.join(vtu_dir, "*_solution_final.vtu")))
    files = [f for f in files if not os.path.basename(f).startswith("b16_")]
    # the finest N of every formulation
    best = {}
    for f in files:
        tag = os.path.basename(f)[:-len("_solution_final.vtu")]
        form, n = tag.rsplit("_N", 1)
        if form not in best or int(n) > int(best[form][0]):
            best[form] = (n, f, tag)
    if not best:
        return
    k = len(best)
    fig, axs = plt.subplots(1, k, figsize=(2.2 * k + 1, 5.2), sharey=True)
    axs = np.atleast_1d(axs)
    pc = None
    for ax, form in zip(axs, sorted(best)):
        n, f, tag = best[form]
        pc, m = draw(ax, f, 3.0, "")
        ax.set_title("%s\nmax cell value %.2f" % (name_of(tag), m), fontsize=7)
        ax.set_xlim(-8, 8)
        ax.set_ylim(-0.5, 22.5)
    axs[0].set_ylabel("z (mm)")
    fig.colorbar(pc, ax=list(axs), label="equivalent plastic strain (cell mean)", shrink=0.8)
    out = os.path.join(fig_dir, "taylor_anvil_ep.png")
    fig.savefig(out, dpi=130, bbox_inches="tight")
    print("wrote", out)


main()
