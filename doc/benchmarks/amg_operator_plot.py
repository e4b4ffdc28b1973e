"""Solve time against DoFs with ML's hierarchy from the tangent and from
the Q1 tangent ('Linear solver/AMG operator'), from the two cantilever
tables of doc/benchmarks/amg_operator.md (or of amg_operator.sh output).

Usage: python3 doc/benchmarks/amg_operator_plot.py doc/benchmarks/amg_operator.md doc/figures/amg_operator.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def tables(path):
    """The rows of each table with an 'AMG operator' column, in order."""
    result, current = [], None
    for line in open(path):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| model |") and "AMG operator" in line:
            current = []
            result.append(current)
        elif current is not None and line.startswith("|") and \
                not line.startswith("|---"):
            current.append(cells)
        elif current is not None and not line.startswith("|"):
            current = None
    return result


def main():
    source, target = sys.argv[1], sys.argv[2]
    found = tables(source)
    fig, axes = plt.subplots(1, len(found), figsize=(5.5 * len(found), 4.2))
    if len(found) == 1:
        axes = [axes]
    for ax, rows, title in zip(axes, found, ["3-D, δ = 1.51 h", "2-D, δ = 2.01 h"]):
        for model, color in [("VCBCPBG V5sn Unl", "C0"),
                             ("VCBCPPG V3sn Unl", "C1"), ("coupled", "C2")]:
            for operator, style in [("tangent", "--o"), ("Q1 cells", "-s")]:
                points = [(int(r[2]), float(r[6])) for r in rows
                          if r[0] == model and r[3] == operator and r[2] != "-"]
                if points:
                    ax.loglog(*zip(*points), style, color=color,
                              label="%s, %s" % (model, operator))
        ax.set_xlabel("DoFs")
        ax.set_ylabel("solve time of 4 Newton solves (s)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("ML hierarchy from the tangent (dashed) or the Q1 tangent (solid)")
    fig.tight_layout()
    fig.savefig(target, dpi=120)


if __name__ == "__main__":
    main()
