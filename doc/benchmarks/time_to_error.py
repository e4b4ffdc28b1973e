#!/usr/bin/env python3
"""Error against wall time for the hard cases (issue 14, deliverable 6).

Reads the result files of three benchmark scripts, all measured in Release
on this machine (see each page for the date and the load):

  cook_3d/results.txt                 B-12, 3-D Cook on irregular particles
                                      (panel a: nu = 0.357; b: 0.4999999)
  punch_3d/results_constraint.txt     B-11, 3-D punch (nu = 0.4, 0.49999; cut families)
  near_incompressible_cook/results.txt 2-D Cook, nu = 0.4999 (regular mesh)

and, for each case, prints the wall time in which each method reaches a
relative error of 10, 5, 2, 1 and 0.5 % and stays there (the wall time
of the coarsest run from which on every finer run of the method has
|u/u_ref - 1| at most that), and the ratio of the fastest finite element to the fastest PG
method. Writes ../figures/time_to_error.png.

Usage (from the repository root): python3 doc/benchmarks/time_to_error.py
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
LEVELS = [0.10, 0.05, 0.02, 0.01, 0.005]


def rows(path):
    with open(os.path.join(HERE, path)) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            yield [x.strip() for x in line.split("|")]


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def cook_3d(panel, reference):
    runs = {}
    for r in rows("cook_3d/results.txt"):
        if r[0] != panel or r[1] == "reference":
            continue
        u, wall = number(r[4]), number(r[9]) if len(r) > 9 else None
        if u is None or wall is None:
            continue
        runs.setdefault(r[1], []).append(
            (int(r[3]), wall, abs(u / reference - 1)))
    return runs


def punch_3d(nu, reference):
    runs = {}
    for r in rows("punch_3d/results_constraint.txt"):
        if r[0] != nu or r[9] != "0" or number(r[6]) != 1.0:
            continue
        error = abs(number(r[5]) / reference - 1)
        if error == 0:  # the reference run itself
            continue
        label = r[1] + ("" if "IUnlP0" not in r[1] else " (nu = 0.5)")
        runs.setdefault(label, []).append((int(r[4]), number(r[8]), error))
    return runs


# the 2-D page runs every code; the plot and table keep the main ones
COOK_2D = {"FEM Q1", "FEM Q1P0", "VCBCPBG V5sn Unl", "VCBCPBG V5sn UnlP0",
           "VCBCPPG V3sn UnlP0", "VCBCPBG V5sn IUnlP0",
           "VCBCPBG V5sn Unl+P1C", "VCPBG V5sn U2P1C", "VCPBG V5sn U1SIG",
           "coupled UnlP0/Q1P0"}


def cook_2d(reference):
    runs = {}
    for r in rows("near_incompressible_cook/results.txt"):
        if r[0] not in COOK_2D or number(r[4]) is None:
            continue
        runs.setdefault(r[0], []).append(
            (int(r[3]), number(r[7]), abs(number(r[4]) / reference - 1)))
    return runs


CASES = [
    ("B-12 a: 3-D Cook, irregular particles, nu = 0.357",
     cook_3d("a", 10.786)),
    ("B-12 b: 3-D Cook, irregular particles, nu = 0.4999999",
     cook_3d("b", 10.812)),
    ("B-11: 3-D punch, nu = 0.4", punch_3d("0.4", -0.0359076)),
    ("B-11: 3-D punch, nu = 0.49999", punch_3d("0.49999", -0.0356778)),
    ("2-D Cook, nu = 0.4999 (regular mesh)", cook_2d(2.713330)),
]


def is_fem(label):
    return label.startswith("FEM")


def time_to(runs, level):
    """The wall time of the coarsest run from which on every finer run of
    the method is within the level: a refinement that crosses the
    reference by luck and leaves it again does not count."""
    result = None
    for dofs, t, e in sorted(runs, reverse=True):
        if e > level:
            break
        result = t
    return result


def table():
    for title, methods in CASES:
        print("\n" + title)
        print("| method | " + " | ".join("%g %%" % (100 * l) for l in LEVELS)
              + " |")
        print("|---" * (len(LEVELS) + 1) + "|")
        for label in sorted(methods, key=lambda m: (not is_fem(m), m)):
            cells = []
            for level in LEVELS:
                t = time_to(methods[label], level)
                cells.append("-" if t is None else "%.2f s" % t)
            print("| %s | %s |" % (label, " | ".join(cells)))
        ratios = []
        for level in LEVELS:
            fem = [time_to(r, level) for m, r in methods.items() if is_fem(m)]
            pg = [time_to(r, level)
                  for m, r in methods.items() if not is_fem(m)]
            fem = min([t for t in fem if t is not None], default=None)
            pg = min([t for t in pg if t is not None], default=None)
            if fem is None and pg is None:
                ratios.append("neither")
            elif fem is None:
                ratios.append("PG only")
            elif pg is None:
                ratios.append("FE only")
            else:
                ratios.append("%.2f" % (fem / pg))
        print("| fastest FE / fastest PG | " + " | ".join(ratios) + " |")


def plot(path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 3, figsize=(13, 8.5))
    axes = axes.flatten()
    colours = {}
    cycle = plt.get_cmap("tab20").colors
    for ax, (title, methods) in zip(axes, CASES):
        for label in sorted(methods, key=lambda m: (not is_fem(m), m)):
            if label not in colours:
                colours[label] = cycle[len(colours) % len(cycle)]
            points = sorted(methods[label])
            t = [p[1] for p in points]
            e = [max(p[2], 1e-5) for p in points]
            ax.loglog(t, e, ("s--" if is_fem(label) else "o-"),
                      label=label, markersize=4, color=colours[label])
        ax.axhspan(1e-5, 0.01, color="0.9", zorder=0)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("wall time (s)")
        ax.set_ylabel("|u / u_ref - 1|")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6, loc="lower left")
    for ax in axes[len(CASES):]:
        ax.axis("off")
    fig.suptitle("Error against wall time (Release, 2 cores; dashed: finite "
                 "elements; grey: below 1 %)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


if __name__ == "__main__":
    table()
    if "--no-plot" not in sys.argv:
        plot(os.path.join(HERE, "..", "figures", "time_to_error.png"))
