#!/usr/bin/env python3
"""B-10 (Table 7.4): the largest single-step angle of each method, the
source's beside pg's with both predictors, from the results files of
torsion_prism.sh. Writes doc/figures/torsion_prism.png.

Usage (from the repository root): /usr/bin/python3 doc/benchmarks/torsion_prism_plot.py
"""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

# Table 7.4 of the source (its second "PPG UnlP0" row is read as PBG UnlP0)
SOURCE = {
    "FEM": 7,
    "FEM H1P0": 42,
    "VCBCPPG V3sn Unl": 17,
    "VCBCPPG V3sn UnlP0": 64,
    "VCBCPBG V5sn Unl": 12,
    "VCBCPBG V5sn UnlP0": 54,
    "VCPBG V5sn U2": 4,
    "VCPBG V5sn U2P1": 58,
    "VCPBG V5sn U2P1C": 47,
    "VCPBG Unl+P1C": 49,
    "VCPBG V5sn U1SIG": 4,
}
LABEL = {
    "FEM": "FEM H1",
    "FEM H1P0": "FEM H1P0",
    "VCBCPPG V3sn Unl": "PPG Unl",
    "VCBCPPG V3sn UnlP0": "PPG UnlP0",
    "VCBCPBG V5sn Unl": "PBG Unl",
    "VCBCPBG V5sn UnlP0": "PBG UnlP0",
    "VCPBG V5sn U2": "PBG U2",
    "VCPBG V5sn U2P1": "PBG U2P1",
    "VCPBG V5sn U2P1C": "PBG U2P1C",
    "VCPBG Unl+P1C": "PBG Unl+P1C",
    "VCPBG V5sn U1SIG": "PBG U1SIG",
}


def largest_angles(path):
    """formulation -> largest single-step angle (degrees)"""
    angles = {}
    for line in open(path):
        if line.startswith("#"):
            continue
        columns = [c.strip() for c in line.split("|")]
        if columns[4] != "-":
            angles[columns[0]] = int(columns[4])
    return angles


DIRECTORY = "doc/benchmarks/torsion_prism/"
boundary = largest_angles(DIRECTORY + "results_N8_boundary_values.txt")
linearized = largest_angles(DIRECTORY + "results_N8_linearized.txt")

methods = list(SOURCE)
y = range(len(methods))
fig, ax = plt.subplots(figsize=(7, 5.5))
height = 0.27
for offset, (name, data, colour) in enumerate(
    [
        ("source (16 x 16 x 80)", SOURCE, "0.6"),
        ("pg, 'Predictor = boundary values'", boundary, "tab:orange"),
        ("pg, 'Predictor = linearized'", linearized, "tab:blue"),
    ]
):
    ax.barh(
        [i + (offset - 1) * height for i in y],
        [data.get(m, 0) for m in methods],
        height,
        label=name,
        color=colour,
    )
ax.set_yticks(list(y))
ax.set_yticklabels([LABEL[m] for m in methods])
ax.invert_yaxis()
ax.set_xlabel("largest angle in one load step (degrees)")
ax.set_title("B-10: torsion of the prism, pg at 8 x 8 x 40 (9,963 DoFs)")
ax.set_xlim(0, 95)
ax.grid(axis="x", alpha=0.3)
ax.legend(loc="lower right", fontsize=8)
fig.tight_layout()
fig.savefig("doc/figures/torsion_prism.png", dpi=120)
