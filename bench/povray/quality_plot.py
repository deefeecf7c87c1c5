#!/usr/bin/python3
"""Draws error against time, one panel per material, from bench/povray/quality.sh's CSV.

Log-log, RMSE (linear) against time in milliseconds (POV-Ray: Trace Time; raytex: GPU frame
time). Each panel shows:
  - POV-Ray's settings against its own converged render (grey dots) and the lower convex hull
    of those points, on which quality.sh interpolates;
  - for the materials whose patterns match in the two scenes (aSolidChecker, aChecker, anImage),
    POV-Ray's settings against raytex's float64 reference too (open squares, the converged
    render among them);
  - raytex's methods against its reference: point and box as lines over 1, 4, 16 and 64 spp,
    coverage at 1 spp as a star, and a dashed line at the error E of its best 1-spp method.
Usage: bench/povray/quality_plot.py QUALITY.csv OUT.png
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from quality_table import SAME_PATTERN, lower_hull  # noqa: E402

COLOURS = {"point": "tab:blue", "box": "tab:orange", "coverage": "tab:red"}


def panel(ax, material, rows):
    pov = [r for r in rows if r["renderer"] == "povray"]
    own = [(float(r["time_ms"]), float(r["rmse"])) for r in pov]
    ax.scatter(*zip(*own), s=14, color="0.45", label="POV-Ray vs its converged render", zorder=3)
    hull = lower_hull(own)
    if len(hull) > 1:
        ax.plot(*zip(*hull), color="0.45", lw=1)
    if material in SAME_PATTERN:
        conv = [r for r in rows if r["renderer"] == "povray-converged"]
        ref = [(float(r["time_ms"]), float(r["rmse_ref"])) for r in pov + conv]
        ax.scatter(*zip(*ref), s=18, facecolors="none", edgecolors="0.2", marker="s",
                   label="POV-Ray vs raytex's reference", zorder=3)
    raytex = [r for r in rows if r["renderer"] == "raytex"]
    for method, colour in COLOURS.items():
        pts = sorted((int(r["setting"].split("spp")[1]), float(r["time_ms"]), float(r["rmse"]))
                     for r in raytex if r["setting"].split()[0] == method)
        if not pts:
            continue
        if len(pts) == 1:
            ax.scatter([pts[0][1]], [pts[0][2]], marker="*", s=120, color=colour, label=f"raytex {method}", zorder=4)
        else:
            ax.plot([p[1] for p in pts], [p[2] for p in pts], "o-", ms=4, color=colour, label=f"raytex {method}")
    one = [r for r in raytex if r["setting"].endswith(" spp1")]
    if one:
        e = min(float(r["rmse"]) for r in one)
        ax.axhline(e, color="tab:red", ls="--", lw=0.8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title(material, fontsize=10)
    ax.grid(True, which="both", lw=0.3, alpha=0.5)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: bench/povray/quality_plot.py QUALITY.csv OUT.png")
    source, chart = sys.argv[1:3]
    try:
        with open(source) as f:
            rows = list(csv.DictReader(f))
    except OSError as err:
        sys.exit(f"quality_plot.py: cannot read {source}: {err.strerror}")
    needed = {"material", "renderer", "setting", "time_ms", "rmse", "rmse_ref"}
    if not rows or not needed <= set(rows[0]):
        sys.exit(f"quality_plot.py: {source} is not a quality.sh CSV (columns {', '.join(sorted(needed))})")
    materials = list(dict.fromkeys(r["material"] for r in rows))
    cols = min(4, len(materials))
    nrows = (len(materials) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(max(4.2 * cols, 9.0), 3.6 * nrows + 0.8), squeeze=False)
    for ax, material in zip(axes.flat, materials):
        panel(ax, material, [r for r in rows if r["material"] == material])
    for ax in list(axes.flat)[len(materials):]:
        ax.axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("time, ms (POV-Ray trace; raytex GPU frame)")
    for ax in axes[:, 0]:
        ax.set_ylabel("RMSE (linear)")
    handles, labels = {}, []
    for ax in axes.flat:
        for h, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, h)
    ncol = min(6 if cols > 2 else 3, len(handles))
    fig.legend(list(handles.values()), list(handles), loc="lower center", ncol=ncol, fontsize=8)
    fig.suptitle("raytex against POV-Ray at equal quality (dashed: raytex's best 1-spp error)", fontsize=11)
    fig.tight_layout(rect=(0, 0.1 if nrows == 1 else 0.06, 1, 0.95))
    fig.savefig(chart, dpi=110)


if __name__ == "__main__":
    main()
