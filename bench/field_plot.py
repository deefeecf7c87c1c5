#!/usr/bin/python3
"""Plots bench/field.sh's output: frame time against the number of spheres, raytex and POV-Ray.

Reads the lines `N, raytex frame ms, POV-Ray trace ms, ratio` (the header line and refused
sizes are skipped for raytex) and draws both series log-log.
Usage: bench/field_plot.py FIELD.txt OUT.png   (env: TITLE, the chart's title)
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    rows = []
    for line in open(path):
        parts = [p.strip() for p in line.split(",")]
        if len(parts) != 4 or not parts[0].isdigit():
            continue
        raytex = float(parts[1]) if not parts[1].startswith("refused") else None
        rows.append((int(parts[0]), raytex, float(parts[2])))
    return rows


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = read(sys.argv[1])
    if not rows:
        sys.exit("field_plot.py: no rows in " + sys.argv[1])
    n = [r[0] for r in rows]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ours = [(r[0], r[1]) for r in rows if r[1] is not None]
    ax.loglog([x for x, _ in ours], [y for _, y in ours], "o-", label="raytex (GPU frame, lavapipe)")
    ax.loglog(n, [r[2] for r in rows], "s-", label="POV-Ray 3.7 (trace time)")
    ax.set_xlabel("spheres (N)")
    ax.set_ylabel("ms per 1920x1080 frame, 2 threads")
    ax.set_title(os.environ.get("TITLE", "Frame time against the number of spheres"))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=100)
    for r in rows:
        print(f"{r[0]:>6}  raytex {r[1] if r[1] is not None else 'refused':>10}  POV-Ray {r[2]:>8}")


if __name__ == "__main__":
    main()
