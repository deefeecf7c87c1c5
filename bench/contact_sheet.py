#!/usr/bin/python3
"""Draws the contact sheet of raytex_bench_accuracy's images: one row per scene; columns: the
float64 reference, then point, box and coverage at one sample per pixel, each beside its FLIP
heat map against the reference (`raytex diff --heatmap`, written next to the images), titled
with its mean FLIP and its RMSE (the float image's, from the CSV). Pixels are shown at an integer scale, without smoothing.
Usage: bench/contact_sheet.py IN.csv OUT.png RAYTEX [SPP]   (SPP: samples per pixel, default 1)
"""
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

METHODS = ["point", "box", "coverage"]


def heatmap(raytex, reference, image):
    """Writes image's FLIP heat map beside it; returns its path and mean FLIP."""
    out = os.path.splitext(image)[0] + "_flip.png"
    report = subprocess.run([raytex, "diff", reference, image, "--json", "--heatmap", out],
                            check=True, capture_output=True, text=True)
    return out, json.loads(report.stdout)["flip"]


def sheet_rows(rows, folder, raytex, spp):
    """Per scene: the reference's path and, per method, (image, heat map, FLIP, RMSE of the float
    image, from the CSV)."""
    scenes = {}
    for row in rows:
        if row["method"] not in METHODS or row["spp"] != spp:
            continue
        reference = os.path.join(folder, row["reference"])
        image = os.path.join(folder, row["image"])
        entry = scenes.setdefault(row["scene"], {"reference": reference})
        entry[row["method"]] = (image,) + heatmap(raytex, reference, image) + (float(row["rmse"]),)
    missing = [s for s, e in scenes.items() if any(m not in e for m in METHODS)]
    if missing or not scenes:
        sys.exit("contact_sheet.py: no %s spp row for every method in %s" % (spp, ", ".join(missing) or "any scene"))
    return scenes


def draw(scenes, chart, spp):
    columns = ["reference"] + [c for m in METHODS for c in (m, m + " FLIP")]
    first = mpimg.imread(next(iter(scenes.values()))["reference"])
    height, width = first.shape[:2]
    scale = 1.0 / 100  # inches per pixel at dpi 100: each image at its own size
    fig, axes = plt.subplots(len(scenes), len(columns), squeeze=False,
                             figsize=(len(columns) * width * scale * 1.02, len(scenes) * (height * scale + 0.3) + 0.5))
    for r, (scene, entry) in enumerate(scenes.items()):
        cells = [(entry["reference"], scene + ": reference")]
        for m in METHODS:
            image, flip_map, flip, rmse = entry[m]
            cells += [(image, "%s  RMSE %.4f" % (m, rmse)), (flip_map, "FLIP %.3f" % flip)]
        for c, (path, title) in enumerate(cells):
            ax = axes[r][c]
            ax.imshow(mpimg.imread(path), interpolation="nearest")
            ax.set_title(title, fontsize=6.5, pad=2)
            ax.axis("off")
    inches = fig.get_figheight()
    fig.suptitle("%s spp against the float64 reference (64x64 spp); FLIP heat maps: dark purple 0, pale yellow 1" % spp,
                 fontsize=8, y=1 - 0.08 / inches)
    fig.subplots_adjust(left=0.005, right=0.995, top=1 - 0.5 / inches, bottom=0.005, wspace=0.02, hspace=0.25)
    fig.savefig(chart, dpi=100)


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit("usage: bench/contact_sheet.py IN.csv OUT.png RAYTEX [SPP]")
    source, chart, raytex = sys.argv[1:4]
    spp = sys.argv[4] if len(sys.argv) == 5 else "1"
    with open(source) as f:
        rows = list(csv.DictReader(f))
    scenes = sheet_rows(rows, os.path.dirname(source), raytex, spp)
    draw(scenes, chart, spp)
    print("wrote", chart)


if __name__ == "__main__":
    main()
