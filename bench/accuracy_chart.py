#!/usr/bin/python3
"""Draws the speed-accuracy chart from raytex_bench_accuracy's CSV.

Adds SSIM (scikit-image's structural_similarity on the sRGB images, against the float64
reference) to each row and plots error against GPU time, log-log: one panel per scene, one
line per method, one point per sample count.
Usage: bench/accuracy_chart.py IN.csv OUT.png OUT.csv
"""
import csv
import os
import platform
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from skimage.metrics import structural_similarity  # noqa: E402


def load(path):
    return mpimg.imread(path)[:, :, :3].astype("float64")  # PNG -> [0, 1]


def main():
    source, chart, table = sys.argv[1:4]
    folder = os.path.dirname(source)
    with open(source) as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        image = load(os.path.join(folder, row["image"]))
        reference = load(os.path.join(folder, row["reference"]))
        row["ssim"] = "%.5f" % structural_similarity(reference, image, channel_axis=2, data_range=1.0)
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["scene", "method", "spp", "gpu_ms", "rmse", "ssim"],
                                extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)

    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    fig, axes = plt.subplots(2, len(scenes), figsize=(3.6 * len(scenes), 6.4), squeeze=False)
    styles = {"point": ("tab:red", "o"), "box": ("tab:blue", "s")}
    for col, scene in enumerate(scenes):
        for row_index, (metric, label) in enumerate([("rmse", "RMSE (linear)"), ("ssim", "1 - SSIM (sRGB)")]):
            ax = axes[row_index][col]
            for method in methods:
                pts = [r for r in rows if r["scene"] == scene and r["method"] == method]
                xs = [float(r["gpu_ms"]) for r in pts]
                ys = [float(r[metric]) if metric == "rmse" else 1.0 - float(r[metric]) for r in pts]
                color, marker = styles.get(method, ("black", "x"))
                ax.plot(xs, ys, marker=marker, color=color, label=method)
                for x, y, r in zip(xs, ys, pts):
                    ax.annotate(r["spp"], (x, y), textcoords="offset points", xytext=(4, 3), fontsize=7)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            if row_index == 0:
                ax.set_title(scene)
            if col == 0:
                ax.set_ylabel(label)
            if row_index == 1:
                ax.set_xlabel("GPU time per frame (ms)")
    axes[0][0].legend(title="texture filter", fontsize=8)
    fig.suptitle("raytex: error vs time, numbers = samples per pixel; reference: float64, 64x64 spp\n"
                 "Mesa lavapipe (CPU Vulkan), %s, 2 threads" % platform.machine(), fontsize=9)
    fig.tight_layout()
    fig.savefig(chart, dpi=110)
    print("wrote", chart, "and", table)


if __name__ == "__main__":
    main()
