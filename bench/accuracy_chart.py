#!/usr/bin/python3
"""Draws the speed-accuracy chart from raytex_bench_accuracy's CSV.

Adds SSIM (of the sRGB images, against the float64 reference, as `raytex diff --json` reports
it: 7x7 uniform windows, sample covariances, the mean over channels) and FLIP (LDR-FLIP's mean,
as `raytex diff` reports it) to each row and plots RMSE and FLIP against GPU time, log-log: two
panels per scene, one line per method, one point per sample count.
Usage: bench/accuracy_chart.py IN.csv OUT.png OUT.csv RAYTEX
"""
import csv
import json
import os
import platform
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def compare(raytex, reference, image):
    """The SSIM and FLIP raytex diff reports for the pair."""
    report = subprocess.run([raytex, "diff", reference, image, "--json"], check=True, capture_output=True, text=True)
    metrics = json.loads(report.stdout)
    return metrics["ssim"], metrics["flip"]


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: bench/accuracy_chart.py IN.csv OUT.png OUT.csv RAYTEX")
    source, chart, table, raytex = sys.argv[1:5]
    folder = os.path.dirname(source)
    with open(source) as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        image = os.path.join(folder, row["image"])
        reference = os.path.join(folder, row["reference"])
        row["ssim"], row["flip"] = ("%.5f" % m for m in compare(raytex, reference, image))
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["scene", "method", "spp", "gpu_ms", "rmse", "ssim", "flip"],
                                extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)

    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    columns = 4
    metrics = [("rmse", "RMSE (linear)"), ("flip", "FLIP (sRGB)")]
    blocks = (len(scenes) + columns - 1) // columns
    fig, axes = plt.subplots(2 * blocks, columns, figsize=(3.4 * columns, 2.7 * 2 * blocks), squeeze=False)
    styles = {"point": ("tab:red", "o"), "box": ("tab:blue", "s"), "coverage": ("tab:green", "D"),
              "box-bilinear": ("tab:brown", "v"), "box-trilinear": ("tab:purple", "^"), "box-ewa": ("tab:cyan", "P"),
              "box-stochastic": ("tab:gray", "x")}
    for index in range(blocks * columns):
        block, col = divmod(index, columns)
        if index >= len(scenes):
            for row_index in range(len(metrics)):
                axes[2 * block + row_index][col].axis("off")
            continue
        scene = scenes[index]
        for row_index, (metric, label) in enumerate(metrics):
            ax = axes[2 * block + row_index][col]
            for method in methods:
                pts = [r for r in rows if r["scene"] == scene and r["method"] == method]
                xs = [float(r["gpu_ms"]) for r in pts]
                ys = [float(r[metric]) for r in pts]
                color, marker = styles.get(method, ("black", "x"))
                ax.plot(xs, ys, marker=marker, color=color, label=method)
                for x, y, r in zip(xs, ys, pts):
                    ax.annotate(r["spp"], (x, y), textcoords="offset points", xytext=(4, 3), fontsize=7)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.tick_params(labelsize=7)
            if row_index == 0:
                ax.set_title(scene, fontsize=9)
            if col == 0:
                ax.set_ylabel(label, fontsize=8)
            if row_index == 1:
                ax.set_xlabel("GPU time per frame (ms)", fontsize=7)
    # The legend of the panel with the most methods (a scene with images).
    richest = max(range(len(scenes)), key=lambda i: len({r["method"] for r in rows if r["scene"] == scenes[i]}))
    block, col = divmod(richest, columns)
    axes[2 * block][col].legend(title="filter (box-*: image method)", fontsize=6, title_fontsize=7)
    fig.suptitle("raytex: error vs time, numbers = samples per pixel; reference: float64, 64x64 spp\n"
                 "Mesa lavapipe (CPU Vulkan), %s, 2 threads" % platform.machine(), fontsize=9)
    fig.tight_layout()
    fig.savefig(chart, dpi=110)
    print("wrote", chart, "and", table)


if __name__ == "__main__":
    main()
